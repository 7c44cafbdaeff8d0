// ErgunGidaspow.hpp: drag law "ErgunGidaspow", Ergun's packed-bed law in
// dense regions and Wen-Yu in dilute ones (Gidaspow 1994).
//
// Equation (model A, |u| = |Uf - Up| interstitial, eps the void fraction):
//   eps <  switchVoidFraction (Ergun 1952 in Gidaspow's form):
//     beta_vol = 150 (1-eps)^2 mu / (eps d^2) + 1.75 (1-eps) rho |u| / d
//   eps >= switchVoidFraction: Wen-Yu, see WenYu.hpp.
// Per particle beta = beta_vol * V_p/(1-eps), V_p = pi d^3/6; one (1-eps)
// cancels analytically, so nothing is divided by (1-eps):
//     beta = 25 pi mu d (1-eps)/eps + (7 pi/24) rho d^2 |u|
// With the pressure-gradient force -V_p grad(p) added separately (DragLaw.hpp),
// a fixed bed then carries exactly the Ergun pressure drop
//     dp/dx = 150 mu U (1-eps)^2/(eps^3 d^2) + 1.75 rho U^2 (1-eps)/(eps^3 d),
// U = eps |u| the superficial velocity (checked in the unit tests).
// The law jumps at the switch (no blending), as in Gidaspow's original.
//
// Validity: Ergun: packed beds of near-spherical particles, eps ~0.35-0.55,
// any Re (viscous + inertial terms); Wen-Yu: 0.8 <= eps <= 1, Re < 1e4.
//
// Parameters (in the drag dictionary):
//     switchVoidFraction  [-]  void fraction where Ergun hands over to Wen-Yu,
//                              in (0, 1]; default 0.8.
//
// References:
//     Gidaspow, D. (1994). Multiphase Flow and Fluidization: Continuum and
//     Kinetic Theory Descriptions. Academic Press, Boston.
//     Ergun, S. (1952). Fluid flow through packed columns. Chemical
//     Engineering Progress 48(2), 89-94.
//     Wen, C.Y., Yu, Y.H. (1966). Mechanics of fluidization. Chemical
//     Engineering Progress Symposium Series 62(62), 100-111.
#pragma once
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

class ErgunGidaspow final : public DragLaw {
public:
    static constexpr const char* typeName = "ErgunGidaspow";
    static constexpr double defaultSwitchVoidFraction = 0.8;

    // Throws ParameterError (an InputError, core/Registry.hpp) unless 0 < switchVoidFraction <= 1.
    explicit ErgunGidaspow(double switchVoidFraction = defaultSwitchVoidFraction);
    // Reads switchVoidFraction (optional); through the registry errors name the file and key.
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;
    double switchVoidFraction() const { return switch_; }

private:
    double switch_;
};

}  // namespace granair
