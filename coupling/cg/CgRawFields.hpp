// CgRawFields.hpp: the additive CG fields of a snapshot (or a time average).
//
// Each is a kernel-weighted sum over particles or contacts, so a time average
// is the weighted sum of snapshots and everything else (velocity, kinetic
// stress, pressure, strain rate, ...) is derived afterwards (CgDerivedFields).
// Per grid point, with psi_i = psi(r - x_i) and the line integral
// Lambda_ij = int_0^1 psi(r - x_i + s r_ij) ds (docs/cg-fields.md):
//   number density    n     = sum psi_i                         [1/m^3]
//   volume fraction   phi   = sum V_i psi_i                     [-]
//   density           rho   = sum m_i psi_i                     [kg/m^3]
//   momentum density  j     = sum m_i v_i psi_i                 [kg/(m^2 s)]
//   momentum flux     K     = sum m_i v_i v_i psi_i (symmetric) [Pa]
//   contact stress    sigma = sum_pairs f_ij (x) r_ij Lambda_ij
//                           + sum_walls f_iw (x) (x_i - c_iw) Lambda_iw  [Pa]
//                     (compression positive; walls from centre to contact point)
//   wall force density t    = sum_walls f_iw psi(r - c_iw)       [N/m^3]
//   diameter moment   sum V_i d_i psi_i (mean diameter = this / phi) [m]
//   inertia density   sum I_i psi_i, I_i = 2/5 m_i a_i^2        [kg/m]
//   angular momentum  sum I_i omega_i psi_i                      [kg/(m s)]
// Vectors are (x, y, z) or, in RZ, (r, theta, z); tensors row-major
// T_ab = a-component of the force times b-component of the branch.
#pragma once
#include <cstddef>
#include <vector>

namespace granair {

namespace cgraw {
enum : int {
    number = 0,
    volume = 1,
    density = 2,
    momentum = 3,       // 3
    momentumFlux = 6,   // 6: xx yy zz xy xz yz
    contactStress = 12, // 9: xx xy xz yx yy yz zx zy zz
    wallForce = 21,     // 3
    diameter = 24,
    inertia = 25,
    angularMomentum = 26,  // 3
    count = 29
};
}  // namespace cgraw

struct CgRawFields {
    std::size_t points = 0;
    std::vector<double> data;  // points x cgraw::count, point-major

    CgRawFields() = default;
    explicit CgRawFields(std::size_t n) : points(n), data(n * cgraw::count, 0.0) {}
    double* at(std::size_t p) { return data.data() + p * cgraw::count; }
    const double* at(std::size_t p) const { return data.data() + p * cgraw::count; }
    // this += weight * other (same size)
    void addScaled(const CgRawFields& other, double weight) {
        for (std::size_t k = 0; k < data.size(); ++k) data[k] += weight * other.data[k];
    }
};

}  // namespace granair
