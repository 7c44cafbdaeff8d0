// Derived CG fields (cg/CgFields.hpp) on prescribed raw fields, and the time
// weights (cg/CgTimeAverage.hpp).
#include <catch2/catch.hpp>

#include <cmath>

#include "cg/CgFields.hpp"
#include "cg/CgTimeAverage.hpp"
#include "core/Error.hpp"

using namespace granair;

namespace {

// Fill raw fields point by point from a function of the point.
template <class F>
CgRawFields fill(const CgGrid& g, F f) {
    CgRawFields raw(g.size());
    for (std::size_t p = 0; p < g.size(); ++p) f(g.point(p), raw.at(p));
    return raw;
}

}  // namespace

TEST_CASE("CG fields: simple shear gives shear rate, pressure, mu, I and viscosity", "[cg][fields]") {
    // u = (G z, 0, 0) on an XZ grid; contact stress P I + tau (e_x e_z + e_z e_x);
    // an isotropic kinetic part pk; phi, rho, d uniform.
    const double G = 12.0, rho = 1500.0, phi = 0.6, d = 1e-3, P = 800.0, tau = 300.0, pk = 15.0;
    const CgGrid g(CgCoordinates::XZ, Box{Vec3::Zero(), Vec3(0.02, 0.01, 0.03)}, {{5, 1, 9}});
    const auto raw = fill(g, [&](const Vec3& x, double* r) {
        const double u = G * x[2];
        r[cgraw::volume] = phi;
        r[cgraw::density] = rho;
        r[cgraw::momentum] = rho * u;
        r[cgraw::momentumFlux + 0] = rho * u * u + pk;  // xx
        r[cgraw::momentumFlux + 1] = pk;                // yy
        r[cgraw::momentumFlux + 2] = pk;                // zz
        r[cgraw::contactStress + 0] = r[cgraw::contactStress + 4] = r[cgraw::contactStress + 8] = P;
        r[cgraw::contactStress + 2] = r[cgraw::contactStress + 6] = tau;
        r[cgraw::diameter] = phi * d;
    });
    const auto f = cgFields(g, raw, CgFieldOptions{});
    const double Pt = P + pk;
    for (std::size_t p = 0; p < g.size(); ++p) {
        INFO("point " << p);
        CHECK(cgField(f, "velocity").values[3 * p] == Approx(G * g.point(p)[2]).epsilon(1e-12));
        CHECK(cgField(f, "velocity_gradient").values[9 * p + 3 * 2 + 0] == Approx(G).epsilon(1e-12));  // d_z u_x
        CHECK(cgField(f, "shear_rate").values[p] == Approx(G).epsilon(1e-12));
        CHECK(cgField(f, "pressure").values[p] == Approx(Pt).epsilon(1e-14));
        CHECK(cgField(f, "shear_stress").values[p] == Approx(tau).epsilon(1e-12));
        CHECK(cgField(f, "J2").values[p] == Approx(tau * tau).epsilon(1e-12));
        CHECK(std::abs(cgField(f, "lode_angle").values[p]) < 1e-12);
        CHECK(cgField(f, "friction_coefficient").values[p] == Approx(tau / Pt).epsilon(1e-12));
        CHECK(cgField(f, "mean_diameter").values[p] == Approx(d).epsilon(1e-14));
        CHECK(cgField(f, "particle_density").values[p] == Approx(rho / phi).epsilon(1e-14));
        CHECK(cgField(f, "inertial_number").values[p] == Approx(G * d / std::sqrt(Pt / (rho / phi))).epsilon(1e-12));
        CHECK(cgField(f, "apparent_viscosity").values[p] == Approx(tau / G).epsilon(1e-12));
        CHECK(cgField(f, "granular_temperature").values[p] == Approx(pk / rho).epsilon(1e-10));
        CHECK(std::abs(cgField(f, "volumetric_strain_rate").values[p]) < 1e-9);
    }
    // no spin field without omega in the dumps
    CHECK_THROWS_WITH(cgField(f, "spin"), Catch::Contains("unknown") && Catch::Contains("pressure"));
}

TEST_CASE("CG fields: RZ gradients: a rigid rotation has no strain, an expansion its hoop rate", "[cg][fields]") {
    const CgGrid g = CgGrid::cylindrical(0, 0, 0.0, 0.05, 0.0, 0.02, 10, 4);
    const double Om = 3.0, e = 0.7;
    const auto raw = fill(g, [&](const Vec3& x, double* r) {
        r[cgraw::volume] = 0.5;
        r[cgraw::density] = 1000.0;
        r[cgraw::momentum + 0] = 1000.0 * e * x[0];   // V_r = e r
        r[cgraw::momentum + 1] = 1000.0 * Om * x[0];  // V_t = Omega r
    });
    const auto f = cgFields(g, raw, CgFieldOptions{});
    for (std::size_t p = 0; p < g.size(); ++p) {
        const double* G = &cgField(f, "velocity_gradient").values[9 * p];
        CHECK(G[0] == Approx(e).epsilon(1e-10));     // d_r V_r
        CHECK(G[1] == Approx(Om).epsilon(1e-10));    // d_r V_t
        CHECK(G[3] == Approx(-Om).epsilon(1e-10));   // -V_t / r
        CHECK(G[4] == Approx(e).epsilon(1e-10));     // V_r / r
        CHECK(cgField(f, "volumetric_strain_rate").values[p] == Approx(2 * e).epsilon(1e-10));
        // the rotation drops out of D; the expansion's D = diag(e, e, 0) gives sqrt(2 D:D) = 2e
        CHECK(cgField(f, "shear_rate").values[p] == Approx(2 * e).epsilon(1e-10));
    }
}

TEST_CASE("CG fields: ratios are NaN where there are no particles", "[cg][fields]") {
    const CgGrid g(CgCoordinates::Z, Box{Vec3::Zero(), Vec3(1, 1, 1)}, {{1, 1, 4}});
    auto raw = fill(g, [&](const Vec3& x, double* r) {
        r[cgraw::volume] = x[2] < 0.5 ? 0.5 : 1e-5;
        r[cgraw::density] = x[2] < 0.5 ? 1000.0 : 0.02;
        r[cgraw::contactStress] = r[cgraw::contactStress + 4] = r[cgraw::contactStress + 8] = 10.0;
    });
    const auto f = cgFields(g, raw, CgFieldOptions{});
    CHECK(std::isfinite(cgField(f, "velocity").values[0]));
    CHECK(std::isnan(cgField(f, "velocity").values[3 * 3]));
    CHECK(std::isnan(cgField(f, "inertial_number").values[3]));
    CHECK(cgField(f, "pressure").values[3] == Approx(10.0));  // stresses stay defined
}

TEST_CASE("CG time average: uniform and Gaussian weights", "[cg][time]") {
    const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    CgTimeAverage u;
    u.from = 0.15, u.to = 0.45;
    const auto wu = u.weights(t);
    CHECK(wu == std::vector<double>{0, 0, 1.0 / 3, 1.0 / 3, 1.0 / 3, 0, 0});
    CgTimeAverage g;
    g.kind = CgTimeAverage::Kind::gauss;
    g.centre = 0.3, g.width = 0.08;  // cut at 3 widths: 0.06 .. 0.54
    const auto wg = g.weights(t);
    double sum = 0;
    for (double w : wg) sum += w;
    CHECK(sum == Approx(1.0).epsilon(1e-15));
    CHECK(wg[0] == 0.0);
    CHECK(wg[6] == 0.0);
    CHECK(wg[2] / wg[3] == Approx(std::exp(-0.5 * std::pow(0.1 / 0.08, 2))).epsilon(1e-12));
    CHECK(wg[2] == Approx(wg[4]).epsilon(1e-12));
    CgTimeAverage none;
    none.from = 2.0, none.to = 3.0;
    CHECK_THROWS_WITH(none.weights(t), Catch::Contains("no snapshot") && Catch::Contains("0 to 0.6"));
    CHECK_THROWS_WITH(CgTimeAverage::parseKind("mean", "option --time-average"),
                      Catch::Contains("option --time-average") && Catch::Contains("gauss uniform"));
}
