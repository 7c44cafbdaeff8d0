// BeetstraVanDerHoefKuipers.hpp: drag law "BeetstraVanDerHoefKuipers", the
// lattice-Boltzmann fit of Beetstra, van der Hoef & Kuipers for monodisperse
// random arrays of spheres.
//
// Equation (phi = 1 - eps the solid fraction, |u| = |Uf - Up| interstitial,
// U = eps |u| the superficial slip velocity):
//     Re = rho d U / mu = rho d eps |u| / mu
//     F(phi, Re) = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi))
//                + 0.413 Re/(24 eps^2) * (1/eps + 3 eps phi + 8.4 Re^-0.343)
//                                      / (1 + 10^(3 phi) Re^-(1+4 phi)/2)
// (eq. 16 of the AIChE J. paper), the drag normalised by the Stokes drag at the
// superficial velocity:  F = F_d / (3 pi mu d U).
//
// Which force: F_d is the DRAG, i.e. the fluid-particle force WITHOUT the
// part due to the mean pressure gradient. In a steady bed the total force on
// a particle is F_d/eps (= F_d + V_p (-grad p)), because eps (-grad p) = n F_d.
// Check: at Re -> 0 the leading term 10 phi/eps^2 gives, with the total force
// n F_d/eps, exactly the Carman-Kozeny pressure drop 180 mu U phi^2/(eps^3 d^2)
// (unit tests). So the correlation is already in model-A form and needs no
// conversion:
//     F_d = beta |u|   =>   beta = 3 pi mu d eps F(phi, Re)     [kg/s]
// This is the normalisation used by MFiX (drag_bvk: F_gs = 18 mu eps phi F/d^2
// per unit volume), OpenFOAM's Beetstra dragModel (K = 18 mu eps phi F/d^2)
// and CFDEMcoupling-PFM's BeetstraDrag for model A (its model B divides by
// eps to get the total force, since there the pressure-gradient force is not
// applied separately).
// Limits: phi -> 0 and Re -> 0 give F -> 1, beta -> 3 pi mu d (Stokes).
// The Re term is evaluated as
//     0.413/(24 eps^2) (Re (1/eps + 3 eps phi) + 8.4 Re^0.657) R/(R + 10^(3 phi)),
//     R = Re^((1+4 phi)/2),
// which is the same expression but has no 0 * inf at |u| = 0.
//
// Validity: fitted to LB data for 0 < phi <= 0.6 (eps >= 0.4) and
// Re <= 1000, monodisperse spheres (the bidisperse extension is not
// implemented).
//
// Parameters: none (fluid rho [kg/m3] and mu [Pa s] come from FluidProperties).
//
// References:
//     Beetstra, R., van der Hoef, M.A., Kuipers, J.A.M. (2007). Drag force of
//     intermediate Reynolds number flow past mono- and bidisperse arrays of
//     spheres. AIChE Journal 53(2), 489-501.
//     van der Hoef, M.A., Beetstra, R., Kuipers, J.A.M. (2005).
//     Lattice-Boltzmann simulations of low-Reynolds-number flow past mono-
//     and bidisperse arrays of spheres: results for the permeability and drag
//     force. Journal of Fluid Mechanics 528, 233-254.
#pragma once
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

class BeetstraVanDerHoefKuipers final : public DragLaw {
public:
    static constexpr const char* typeName = "BeetstraVanDerHoefKuipers";
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;

    // The dimensionless drag F(phi, Re) of the paper (eq. 16).
    static double dimensionlessDrag(double eps, double Re);
};

}  // namespace granair
