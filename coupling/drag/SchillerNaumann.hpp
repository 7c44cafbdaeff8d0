// SchillerNaumann.hpp: drag law "SchillerNaumann", an isolated sphere (no
// crowding correction), for dilute regions only.
//
// Equation (Schiller & Naumann 1933; the Re >= 1000 plateau as usual in CFD):
//     Re = rho d |u| / mu
//     Cd = 24/Re (1 + 0.15 Re^0.687)   for Re < 1000
//     Cd = 0.44                         for Re >= 1000
//     F  = 1/2 Cd rho (pi d^2/4) |u| u   =>   beta = (pi/8) Cd rho d^2 |u|
// Written with Cd*Re, which stays finite as |u| -> 0:
//     beta = (pi/8) mu d (Cd Re)   ->   3 pi mu d (Stokes) at Re -> 0.
// |u| = |Uf - Up|. The void fraction is checked but not used.
//
// Validity: single sphere in unbounded fluid, Re up to ~2e5 (below the drag
// crisis); the fit of the Re < 1000 branch is within ~5 % of the standard
// drag curve (Clift, Grace & Weber 1978). Not for packed or dense regions.
//
// Parameters: none (fluid rho [kg/m3] and mu [Pa s] come from FluidProperties).
//
// Reference:
//     Schiller, L., Naumann, A. (1933). Ueber die grundlegenden Berechnungen
//     bei der Schwerkraftaufbereitung (often cited as "A drag coefficient
//     correlation").
//     Zeitschrift des Vereins Deutscher Ingenieure 77, 318-320.
#pragma once
#include <cmath>
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

// Cd*Re of the Schiller-Naumann correlation (shared with WenYu and
// ErgunGidaspow, which apply it at the void-fraction-weighted Reynolds number).
inline double schillerNaumannCdRe(double Re) {
    return Re < 1000 ? 24.0 * (1.0 + 0.15 * std::pow(Re, 0.687)) : 0.44 * Re;
}

class SchillerNaumann final : public DragLaw {
public:
    static constexpr const char* typeName = "SchillerNaumann";
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;
};

}  // namespace granair
