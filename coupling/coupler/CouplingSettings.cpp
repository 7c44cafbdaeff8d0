// CouplingSettings.cpp: see CouplingSettings.hpp.
#include "coupler/CouplingSettings.hpp"

namespace granair {

CouplingSettings CouplingSettings::read(const Dictionary& dict) {
    CouplingSettings s;
    s.couplingInterval = static_cast<int>(dict.getDouble("couplingInterval", 1, 1e9));
    if (dict.getDouble("couplingInterval") != s.couplingInterval)
        fail<InputError>(dict.where("couplingInterval"), ": expected a whole number of DEM steps");
    s.airOn = dict.getBool("air", true);
    const std::string coupling = dict.getString("momentumCoupling", "two-way");
    if (coupling != "two-way" && coupling != "one-way")
        fail<InputError>(dict.where("momentumCoupling"), ": '", coupling,
                         "', expected two-way (the default) or one-way");
    s.oneWay = coupling == "one-way";
    if (dict.has("coarseGrainingFactor"))
        s.coarseGrainingFactor = dict.getDouble("coarseGrainingFactor", 1.0, 1000.0);
    if (dict.has("voidFractionFloor"))
        s.voidFractionFloor = dict.getDouble("voidFractionFloor", 1e-3, 0.99);
    s.gravity = dict.getVec3("gravity", s.gravity);
    if (dict.has("forces")) {
        const Dictionary& f = dict.subDict("forces");
        s.dragForce = f.getBool("drag", true);
        s.pressureGradientForce = f.getBool("pressureGradient", true);
        s.buoyancyForce = f.getBool("buoyancy", true);
        s.forcesApplied = f.getBool("applied", true);
    }
    // Required with the air on. With the air off (a DEM-only run of the same
    // case) the drag law is not used but still checked when given, and the
    // void-fraction model (default centre) gives the run's void-fraction output.
    if (s.airOn || dict.has("drag")) s.drag = dragLaws().create(dict.subDict("drag"));
    if (s.airOn || dict.has("voidFraction"))
        s.voidFraction = voidFractionModels().create(dict.subDict("voidFraction"));
    else
        s.voidFraction = voidFractionModels().create(Dictionary::fromString("type centre;", dict.source()));
    return s;
}

}  // namespace granair
