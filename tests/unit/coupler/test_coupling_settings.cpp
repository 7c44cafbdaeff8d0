// CouplingSettings: defaults, and errors that name the file and key.
#include <catch2/catch.hpp>

#include "coupler/CouplingSettings.hpp"

using Catch::Matchers::Contains;
using granair::CouplingSettings;
using granair::Dictionary;

TEST_CASE("coupling settings read the case dictionary", "[coupler]") {
    auto d = Dictionary::fromString(R"(
        couplingInterval 50; coarseGrainingFactor 2; voidFractionFloor 0.35;
        drag { type ErgunGidaspow; } voidFraction { type centre; }
        forces { buoyancy off; })", "constant/couplingProperties");
    auto s = CouplingSettings::read(d);
    CHECK(s.couplingInterval == 50);
    CHECK(s.coarseGrainingFactor == 2);
    CHECK(s.voidFractionFloor == 0.35);
    CHECK(s.airOn);
    CHECK(s.drag->name() == "ErgunGidaspow");
    CHECK(s.voidFraction->name() == "centre");
    CHECK_FALSE(s.buoyancyForce);
    CHECK(s.pressureGradientForce);
    CHECK_FALSE(s.oneWay);
    CHECK(s.forcesApplied);
}

TEST_CASE("forces are applied by default, computed only with applied off", "[coupler]") {
    const std::string base = "couplingInterval 5; drag { type ErgunGidaspow; } voidFraction { type centre; } ";
    const auto off = CouplingSettings::read(Dictionary::fromString(base + "forces { applied off; }", "cp"));
    CHECK_FALSE(off.forcesApplied);
    CHECK(off.dragForce);  // the forces themselves are still computed
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(base + "forces { applied maybe; }", "cp")),
                      Contains("cp") && Contains("applied"));
}

TEST_CASE("momentum coupling is two-way by default, one-way on request", "[coupler]") {
    const std::string base = "couplingInterval 5; drag { type ErgunGidaspow; } voidFraction { type centre; } ";
    CHECK(CouplingSettings::read(Dictionary::fromString(base + "momentumCoupling one-way;", "cp")).oneWay);
    CHECK_FALSE(CouplingSettings::read(Dictionary::fromString(base + "momentumCoupling two-way;", "cp")).oneWay);
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(base + "momentumCoupling oneway;", "cp")),
                      Contains("cp") && Contains("momentumCoupling") && Contains("'oneway'") &&
                          Contains("expected two-way"));
}

TEST_CASE("coupling settings reject bad values naming file and key", "[coupler]") {
    const std::string base = "drag { type ErgunGidaspow; } voidFraction { type centre; } ";
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(base, "cp")),
                      Contains("cp") && Contains("couplingInterval") && Contains("missing"));
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(base + "couplingInterval 0;", "cp")),
                      Contains("couplingInterval") && Contains("out of range"));
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(base + "couplingInterval 2.5;", "cp")),
                      Contains("whole number"));
    CHECK_THROWS_WITH(
        CouplingSettings::read(Dictionary::fromString(base + "couplingInterval 5; voidFractionFloor 1.5;", "cp")),
        Contains("voidFractionFloor") && Contains("out of range"));
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(
                          "couplingInterval 5; drag { type Nope; } voidFraction { type centre; }", "cp")),
                      Contains("unknown drag law 'Nope'") && Contains("ErgunGidaspow"));
    // with the air off no models are needed: no drag law, the centre void
    // fraction for the output field
    auto off = CouplingSettings::read(Dictionary::fromString("couplingInterval 5; air off;", "cp"));
    CHECK_FALSE(off.airOn);
    CHECK_FALSE(off.drag);
    CHECK(off.voidFraction->name() == "centre");
    // ... but the ones given are still checked
    CHECK_THROWS_WITH(CouplingSettings::read(Dictionary::fromString(
                          "couplingInterval 5; air off; voidFraction { type middle; }", "cp")),
                      Contains("unknown void-fraction model 'middle'"));
}
