// ShearRate.hpp: the shear-rate magnitude the inertial-number rheologies use.
//
//     gammaDot = sqrt(2 D:D),   D = (grad U + grad U^T)/2
// D:D = sum_ij D_ij D_ij. This is the magnitude of Jop, Forterre & Pouliquen
// (2006), |gammaDot| = sqrt(gammaDot_ij gammaDot_ij / 2) with
// gammaDot_ij = 2 D_ij, so that simple shear u = (G y, 0, 0) gives exactly
// gammaDot = |G|. A rigid rotation gives 0 (only the symmetric part counts).
// The deviatoric part is not taken: in an incompressible flow tr D = 0 and
// the two agree; in a compressible one the dilation contributes too.
//
//     deviatoricShearRate = sqrt(2 D':D'),  D' = D - (tr D / 3) 1
// is the shear rate of a flow that changes volume (granairContinuumFoam with
// dilatancy, Dilatancy.H): a pure dilation gives 0. There the dilation is
// itself driven by the shear rate, and with the full D it would feed back
// into its own cause (measured: div U growing to 1e5 1/s within 0.03 s on
// the MCC hopper).
//
// Reference: Jop, P., Forterre, Y., Pouliquen, O. (2006). A constitutive law
// for dense granular flows. Nature 441, 727-730.
#pragma once
#include <Eigen/Core>

namespace granair {

// gradU(i, j) = dU_j/dx_i or dU_i/dx_j: either convention, D is symmetric. [1/s]
double shearRate(const Eigen::Matrix3d& gradU);
// sqrt(2 D':D') with the deviator D' of D. [1/s]
double deviatoricShearRate(const Eigen::Matrix3d& gradU);

}  // namespace granair
