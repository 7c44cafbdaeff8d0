// WenYu.hpp: drag law "WenYu", single-sphere drag with the Wen-Yu crowding
// correction eps^-2.65 (the dilute branch of Gidaspow's model).
//
// Equation, in the form of Gidaspow (1994), |u| = |Uf - Up| interstitial:
//     Re       = eps rho d |u| / mu
//     Cd       = 24/Re (1 + 0.15 Re^0.687)  for Re < 1000,  0.44 for Re >= 1000
//     beta_vol = 3/4 Cd eps (1-eps) rho |u| / d * eps^-2.65     [kg/(m3 s)]
// per particle beta = beta_vol * V_p / (1-eps) with V_p = pi d^3/6, so (1-eps)
// cancels and, with Cd rho d |u| = Cd Re mu / eps,
//     beta = (pi/8) Cd rho d^2 |u| eps^-1.65 = (pi/8) mu d (Cd Re) eps^-2.65
// which is finite at eps = 1 and at |u| = 0 (3 pi mu d eps^-2.65 there).
// beta excludes the pressure-gradient force (model A, see DragLaw.hpp).
//
// Validity: Wen & Yu fitted fluidisation/sedimentation data for roughly
// 0.4 < eps < 1 and 0.01 < Re < 1e4; it underpredicts the Ergun pressure
// drop in packed beds, so Gidaspow uses it only for eps > 0.8.
//
// Parameters: none (fluid rho [kg/m3] and mu [Pa s] come from FluidProperties).
//
// References:
//     Wen, C.Y., Yu, Y.H. (1966). Mechanics of fluidization. Chemical
//     Engineering Progress Symposium Series 62(62), 100-111.
//     Gidaspow, D. (1994). Multiphase Flow and Fluidization: Continuum and
//     Kinetic Theory Descriptions. Academic Press, Boston.
#pragma once
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

class WenYu final : public DragLaw {
public:
    static constexpr const char* typeName = "WenYu";
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;

    // The formula alone, for inputs already checked (used by ErgunGidaspow).
    static double coefficient(double d, double eps, double slip, const FluidProperties& f);
};

}  // namespace granair
