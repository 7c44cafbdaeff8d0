// CgFields.hpp: the CG fields a user sees, derived from the raw fields.
//
// Definitions (docs/cg-fields.md), with S = sym(sigma):
//   velocity V = j / rho;  kinetic stress sigma_k = K - rho V V;
//   stress sigma = sigma_k + sigma_c (compression positive: a pressure is > 0;
//     sigma_ab is the a-component of force per area on a surface with
//     normal b, so statics reads d_b sigma_ab = rho g_a + t_a);
//   pressure P = tr(sigma)/3;  deviator tau = S - P I;
//   J2 = tau:tau / 2, J3 = det(tau), shear stress tau_eq = sqrt(J2),
//   Lode angle asin(-(3 sqrt 3 / 2) J3 / J2^(3/2)) / 3;
//   velocity gradient G_ab = d_a V_b = (d_a j_b - V_b d_a rho)/rho by central
//     differences of j and rho on the grid (one-sided at its edges, zero along
//     averaged directions; RZ: the cylindrical gradient with G_tr = -V_t/r,
//     G_tt = V_r/r);  strain rate D = sym(G);  shear rate gammaDot = sqrt(2 D:D)
//     (rheology/ShearRate.hpp);  volumetric strain rate tr(D);
//   granular temperature T = tr(sigma_k) / (3 rho);
//   mean diameter d = sum V_i d_i psi_i / phi;  particle density rho_p = rho / phi;
//   inertial number I = gammaDot d / sqrt(P / rho_p);  friction mu = tau_eq / P;
//   apparent viscosity eta = tau_eq / gammaDot;  spin = sum I_i w_i psi_i / sum I_i psi_i.
// Ratios are NaN where phi < minVolumeFraction (no particles to speak of),
// and I, mu where P <= 0, eta where gammaDot = 0.
#pragma once
#include <string>
#include <vector>

#include "cg/CgGrid.hpp"
#include "cg/CgRawFields.hpp"

namespace granair {

struct CgField {
    std::string name;   // e.g. "volume_fraction", "stress"
    std::string unit;   // e.g. "Pa"
    int components = 1; // 1 (scalar), 3 (vector), 9 (tensor, row-major)
    std::vector<double> values;  // points x components
};

struct CgFieldOptions {
    double minVolumeFraction = 1e-3;
    bool spin = false;  // omega was in the dump
};

std::vector<CgField> cgFields(const CgGrid& grid, const CgRawFields& raw, const CgFieldOptions& opt);

// The field named `name` (InputError listing the names if absent).
const CgField& cgField(const std::vector<CgField>& fields, const std::string& name);

}  // namespace granair
