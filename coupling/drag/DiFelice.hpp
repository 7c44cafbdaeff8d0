// DiFelice.hpp: drag law "DiFelice", Dallavalle's single-sphere drag with Di
// Felice's Reynolds-dependent voidage function eps^-chi.
//
// Equation (|u| = |Uf - Up| interstitial, eps the void fraction):
//     Re  = rho d eps |u| / mu
//     Cd  = (0.63 + 4.8/sqrt(Re))^2                       (Dallavalle 1948)
//     chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2)
//     F   = 1/2 Cd rho (pi d^2/4) eps^2 |u| u eps^-chi
//   =>  beta = (pi/8) Cd rho d^2 eps^(2-chi) |u|
// Written with Cd*Re = (0.63 sqrt(Re) + 4.8)^2, which stays finite as
// |u| -> 0, and Cd rho d |u| = Cd Re mu / eps:
//     beta = (pi/8) mu d eps^(1-chi) (0.63 sqrt(Re) + 4.8)^2
// At Re = 0, chi = 3.7 and beta = 2.88 pi mu d eps^-2.7: Dallavalle's Cd tends
// to 23.04/Re, so the creeping limit is 0.96 x Stokes (a property of the
// correlation, not an error here). beta is used as the model-A drag: the
// pressure-gradient force is added separately (DragLaw.hpp), which is the
// usual way Di Felice's law is applied in CFD-DEM codes.
//
// Validity: fitted to fixed/fluidised bed and sedimentation data for
// 1e-2 < Re < 1e4 and about 0.4 < eps < 1.
//
// Parameters: none (fluid rho [kg/m3] and mu [Pa s] come from FluidProperties).
//
// References:
//     Di Felice, R. (1994). The voidage function for fluid-particle
//     interaction systems. International Journal of Multiphase Flow 20(1),
//     153-159.
//     Dallavalle, J.M. (1948). Micromeritics: The Technology of Fine
//     Particles, 2nd ed. Pitman, New York.
#pragma once
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

class DiFelice final : public DragLaw {
public:
    static constexpr const char* typeName = "DiFelice";
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;
};

}  // namespace granair
