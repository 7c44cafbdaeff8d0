// CgFields.cpp: see CgFields.hpp.
#include "cg/CgFields.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "rheology/ShearRate.hpp"

namespace granair {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// d(raw component)/d(axis) at grid point (i, j, k): central differences,
// second-order one-sided at the edges, zero along averaged axes.
double derivative(const CgGrid& g, const CgRawFields& raw, int comp, int axis, const int ijk[3]) {
    const int n = g.count(axis);
    if (!g.resolved(axis) || n < 2) return 0.0;
    auto at = [&](int q) {
        int m[3] = {ijk[0], ijk[1], ijk[2]};
        m[axis] = q;
        return raw.at(g.index(m[0], m[1], m[2]))[comp];
    };
    const int q = ijk[axis];
    const double h = g.spacing(axis);
    if (n == 2) return (at(1) - at(0)) / h;
    if (q == 0) return (-3.0 * at(0) + 4.0 * at(1) - at(2)) / (2.0 * h);
    if (q == n - 1) return (3.0 * at(n - 1) - 4.0 * at(n - 2) + at(n - 3)) / (2.0 * h);
    return (at(q + 1) - at(q - 1)) / (2.0 * h);
}

CgField make(const char* name, const char* unit, int comps, std::size_t points) {
    CgField f;
    f.name = name;
    f.unit = unit;
    f.components = comps;
    f.values.assign(points * comps, 0.0);
    return f;
}

}  // namespace

std::vector<CgField> cgFields(const CgGrid& grid, const CgRawFields& raw, const CgFieldOptions& opt) {
    const std::size_t N = grid.size();
    if (raw.points != N) fail("cgFields: ", raw.points, " raw points for a grid of ", N);
    enum {
        fN, fPhi, fRho, fJ, fV, fSk, fSc, fS, fT, fP, fTau, fJ2, fJ3, fLode, fG, fD, fGd, fDv, fTg, fDm, fRp, fI, fMu,
        fEta, fW, fCount
    };
    std::vector<CgField> f(fCount);
    f[fN] = make("number_density", "1/m^3", 1, N);
    f[fPhi] = make("volume_fraction", "-", 1, N);
    f[fRho] = make("density", "kg/m^3", 1, N);
    f[fJ] = make("momentum_density", "kg/(m^2 s)", 3, N);
    f[fV] = make("velocity", "m/s", 3, N);
    f[fSk] = make("kinetic_stress", "Pa", 9, N);
    f[fSc] = make("contact_stress", "Pa", 9, N);
    f[fS] = make("stress", "Pa", 9, N);
    f[fT] = make("wall_force_density", "N/m^3", 3, N);
    f[fP] = make("pressure", "Pa", 1, N);
    f[fTau] = make("shear_stress", "Pa", 1, N);
    f[fJ2] = make("J2", "Pa^2", 1, N);
    f[fJ3] = make("J3", "Pa^3", 1, N);
    f[fLode] = make("lode_angle", "rad", 1, N);
    f[fG] = make("velocity_gradient", "1/s", 9, N);
    f[fD] = make("strain_rate", "1/s", 9, N);
    f[fGd] = make("shear_rate", "1/s", 1, N);
    f[fDv] = make("volumetric_strain_rate", "1/s", 1, N);
    f[fTg] = make("granular_temperature", "m^2/s^2", 1, N);
    f[fDm] = make("mean_diameter", "m", 1, N);
    f[fRp] = make("particle_density", "kg/m^3", 1, N);
    f[fI] = make("inertial_number", "-", 1, N);
    f[fMu] = make("friction_coefficient", "-", 1, N);
    f[fEta] = make("apparent_viscosity", "Pa s", 1, N);
    f[fW] = make("spin", "rad/s", 3, N);

    const bool rz = grid.isCylindrical();
    for (std::size_t p = 0; p < N; ++p) {
        const double* r = raw.at(p);
        const double rho = r[cgraw::density], phi = r[cgraw::volume];
        const bool filled = phi >= opt.minVolumeFraction && rho > 0.0;
        f[fN].values[p] = r[cgraw::number];
        f[fPhi].values[p] = phi;
        f[fRho].values[p] = rho;
        Eigen::Vector3d j(r[cgraw::momentum], r[cgraw::momentum + 1], r[cgraw::momentum + 2]);
        const Eigen::Vector3d V = rho > 0.0 ? Eigen::Vector3d(j / rho) : Eigen::Vector3d::Zero();
        const double* K = r + cgraw::momentumFlux;  // xx yy zz xy xz yz
        Eigen::Matrix3d Kt;
        Kt << K[0], K[3], K[4], K[3], K[1], K[5], K[4], K[5], K[2];
        const Eigen::Matrix3d Sk = Kt - rho * V * V.transpose();
        Eigen::Matrix3d Sc;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) Sc(a, b) = r[cgraw::contactStress + 3 * a + b];
        const Eigen::Matrix3d S = Sk + Sc;
        for (int a = 0; a < 3; ++a) {
            f[fJ].values[3 * p + a] = j[a];
            f[fV].values[3 * p + a] = filled ? V[a] : nan;
            f[fT].values[3 * p + a] = r[cgraw::wallForce + a];
            for (int b = 0; b < 3; ++b) {
                f[fSk].values[9 * p + 3 * a + b] = Sk(a, b);
                f[fSc].values[9 * p + 3 * a + b] = Sc(a, b);
                f[fS].values[9 * p + 3 * a + b] = S(a, b);
            }
        }
        const double P = S.trace() / 3.0;
        const Eigen::Matrix3d tau = 0.5 * (S + S.transpose()) - P * Eigen::Matrix3d::Identity();
        const double J2 = 0.5 * (tau.array() * tau.array()).sum();
        const double J3 = tau.determinant();
        const double tauEq = std::sqrt(J2);
        f[fP].values[p] = P;
        f[fTau].values[p] = tauEq;
        f[fJ2].values[p] = J2;
        f[fJ3].values[p] = J3;
        f[fLode].values[p] =
            J2 > 0.0 ? std::asin(std::clamp(-1.5 * std::sqrt(3.0) * J3 / std::pow(J2, 1.5), -1.0, 1.0)) / 3.0 : nan;

        // Velocity gradient from d(j) and d(rho).
        const std::size_t nx = grid.count(0), ny = grid.count(1);
        const int ijk[3] = {int(p % nx), int((p / nx) % ny), int(p / (nx * ny))};
        Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
        if (filled) {
            for (int a = 0; a < 3; ++a) {
                const double drho = derivative(grid, raw, cgraw::density, a, ijk);
                for (int b = 0; b < 3; ++b)
                    G(a, b) = (derivative(grid, raw, cgraw::momentum + b, a, ijk) - V[b] * drho) / rho;
            }
            if (rz) {
                // Axisymmetric: no theta derivatives; hoop terms from the frame's rotation.
                G.row(1).setZero();
                const double rr = grid.point(p)[0];
                if (rr > 0.0) {
                    G(1, 0) = -V[1] / rr;
                    G(1, 1) = V[0] / rr;
                }
            }
        }
        const Eigen::Matrix3d D = 0.5 * (G + G.transpose());
        const double gd = filled ? shearRate(G) : nan;
        for (int a = 0; a < 9; ++a) {
            f[fG].values[9 * p + a] = filled ? G(a / 3, a % 3) : nan;
            f[fD].values[9 * p + a] = filled ? D(a / 3, a % 3) : nan;
        }
        f[fGd].values[p] = gd;
        f[fDv].values[p] = filled ? D.trace() : nan;
        f[fTg].values[p] = filled ? Sk.trace() / (3.0 * rho) : nan;
        const double d = filled ? r[cgraw::diameter] / phi : nan;
        const double rhoP = filled ? rho / phi : nan;
        f[fDm].values[p] = d;
        f[fRp].values[p] = rhoP;
        const bool loaded = filled && P > 0.0;
        f[fI].values[p] = loaded ? gd * d / std::sqrt(P / rhoP) : nan;
        f[fMu].values[p] = loaded ? tauEq / P : nan;
        f[fEta].values[p] = filled && gd > 0.0 ? tauEq / gd : nan;
        const double inertia = r[cgraw::inertia];
        for (int a = 0; a < 3; ++a)
            f[fW].values[3 * p + a] = filled && inertia > 0.0 ? r[cgraw::angularMomentum + a] / inertia : nan;
    }
    if (!opt.spin) f.pop_back();
    return f;
}

const CgField& cgField(const std::vector<CgField>& fields, const std::string& name) {
    for (const auto& f : fields)
        if (f.name == name) return f;
    std::string list;
    for (const auto& f : fields) list += " " + f.name;
    fail<InputError>("CG field '", name, "' unknown. Fields:", list);
}

}  // namespace granair
