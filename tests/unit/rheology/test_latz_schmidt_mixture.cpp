// The latzSchmidt closure inside the incompressible mixture solver: the
// equation-of-state inversion c(p, T), the homogeneous-shear balance of the
// granular-temperature equation (tau/p = tan(phi) = sqrt(eta0 eps0), the
// relation reference case A states for its calibration), and the per-cell
// terms granairContinuumFoam assembles (GranularTemperatureModel.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "rheology/GranularTemperatureModel.hpp"
#include "rheology/LatzSchmidt.hpp"

using granair::Dictionary;
using granair::GranularTemperatureModel;
using granair::LatzSchmidt;
using Catch::Matchers::Contains;

namespace {

// Lactose (reference case A): c0, cMax, T0, eta0, lambda0, eps0.
const LatzSchmidt::Parameters lac{0.5579, 0.5771, 0.41, 0.00052, 0.001, 332.84};
LatzSchmidt lactose() { return LatzSchmidt(lac); }

// Closed-form steady simple shear at fixed pressure q = p/rho_p [m2/s2]:
// the balance eta gammaDot^2 = eps_r p_k is T g_c = K, K = (eta0/eps0) gammaDot^2
// (LatzSchmidt.hpp), with g_c from the equation of state at (q, T):
//   c <= c0:  1 - c/cMax = T/(T + q/cMax)                       => T = K - q/cMax
//   c >  c0:  1 - c/cMax = (cMax(T+T0) - T0 c0)/(cMax(T+T0) + q)
//             => cMax T^2 + (cMax T0 + q - K cMax) T - K T0 (cMax - c0) = 0 (one positive root).
double steadyShearTemperatureAtPressure(double q, double gammaDot) {
    const double K = lac.eta0 / lac.eps0 * gammaDot * gammaDot;
    const double a = lac.cMax, b = lac.cMax * lac.T0 + q - K * lac.cMax, c = -K * lac.T0 * (lac.cMax - lac.c0);
    const double plastic = 2.0 * c / (-b - std::sqrt(b * b - 4.0 * a * c));  // positive root, no cancellation
    if (lactose().solidFraction(q, plastic) > lac.c0) return plastic;
    return K - q / lac.cMax;
}

}  // namespace

TEST_CASE("latzSchmidt: the equation of state inverted for c", "[rheology][latzSchmidt]") {
    const LatzSchmidt m = lactose();

    SECTION("round trip c -> p(c, T) -> c to 1e-10, below and above c0") {
        for (double T : {1e-12, 1e-8, 1e-4, 1e-2, 1.0})
            for (double c : {1e-6, 0.01, 0.2, 0.5, 0.55, 0.5579, 0.558, 0.565, 0.575, 0.577, 0.57709}) {
                const double q = m.values(c, T).p;
                CHECK(std::abs(m.solidFraction(q, T) - c) <= 1e-10);
            }
    }
    SECTION("p = 0 (and tension) gives c = 0; a huge p stays below cMax") {
        CHECK(m.solidFraction(0.0, 1e-6) == 0.0);
        CHECK(m.solidFraction(-50.0, 1e-6) == 0.0);
        for (double q : {1e6, 1e12, 1e20, 1e300}) {
            const double c = m.solidFraction(q, 1e-12);
            CHECK(c < lac.cMax);
            CHECK(c > lac.cMax - 1e-5);
            CHECK_NOTHROW(m.values(c, 1e-12));  // g_c finite: usable by the closure
        }
    }
    SECTION("c grows with p at fixed T (the root is unique)") {
        double last = -1;
        for (double q = 1e-14; q < 1e8; q *= 1.7) {
            const double c = m.solidFraction(q, 1e-6);
            CHECK(c > last);
            last = c;
        }
    }
    SECTION("bad state: non-finite p or T <= 0, naming the value") {
        CHECK_THROWS_AS(m.solidFraction(NAN, 1e-6), granair::InputError);
        CHECK_THROWS_WITH(m.solidFraction(1.0, 0.0), Contains("granular temperature T = 0 m2/s2"));
    }
}

TEST_CASE("latzSchmidt: homogeneous simple shear balance gives tau/p = sqrt(eta0 eps0)", "[rheology][latzSchmidt]") {
    const LatzSchmidt m = lactose();
    const double tanPhi = std::sqrt(lac.eta0 * lac.eps0);  // 0.416, reference case A
    REQUIRE(m.tanFrictionAngle() == Approx(0.41602499925).epsilon(1e-10));  // sqrt(0.00052 x 332.84), phi = 22.59 deg

    SECTION("at fixed c, T* = eta0 gammaDot^2/(eps0 g_c)") {
        for (double c : {0.1, 0.5, 0.5579, 0.56, 0.57, 0.5770})
            for (double g : {1e-3, 1.0, 50.0}) {
                const double T = m.steadyShearTemperature(c, g);
                const auto v = m.values(c, T);
                // Heating eta gammaDot^2 = 2 eta D:D balances eps_r p_k ...
                CHECK(v.eta * g * g == Approx(v.epsR * v.pK).epsilon(1e-12));
                // ... and the stress ratio is the calibrated friction.
                CHECK(v.eta * g / v.p == Approx(tanPhi).epsilon(1e-12));
            }
    }

    SECTION("at fixed pressure, the solver's implicit-sink iteration T <- P/(S/T) converges to it") {
        // No cap (etaMax huge): the balance of the model itself.
        const GranularTemperatureModel model(m, {1060.0, 1e300, 1e-12});
        for (double p : {5.0, 300.0, 1000.0, 5000.0})
            for (double g : {0.1, 10.0, 200.0}) {
                double T = 1e-12;  // start at the floor, as the powder at rest
                for (int it = 0; it < 10000; ++it) {
                    const auto cell = model.evaluate(p, T, g);
                    const double next = cell.production / cell.sinkRate;
                    const bool done = std::abs(next - T) <= 1e-15 * T;
                    T = next;
                    if (done) break;
                }
                const auto cell = model.evaluate(p, T, g);
                INFO("p = " << p << " Pa, gammaDot = " << g << " 1/s, T = " << T << ", c = " << cell.c);
                CHECK(T == Approx(steadyShearTemperatureAtPressure(p / 1060.0, g)).epsilon(1e-10));
                CHECK(cell.production == Approx(cell.dissipation).epsilon(1e-12));
                CHECK(cell.eta * g / p == Approx(tanPhi).epsilon(1e-12));
            }
    }
}

TEST_CASE("latzSchmidt in the mixture solver: per-cell terms, cap and bad input", "[rheology][latzSchmidt]") {
    const GranularTemperatureModel model(lactose(), {1060.0, 1e3, 1e-12});

    SECTION("below the cap: eta = rho_p eta_LS, production = eta_LS gammaDot^2, sink rate = eps_r p_k / T") {
        const double p = 800.0, T = 1e-5, g = 3.0;
        const auto cell = model.evaluate(p, T, g);
        const auto v = lactose().values(cell.c, T);
        REQUIRE_FALSE(cell.capped);
        CHECK(v.p == Approx(p / 1060.0).epsilon(1e-12));  // the EOS reproduces the pressure
        CHECK(cell.eta == Approx(1060.0 * v.eta).epsilon(1e-14));
        CHECK(cell.lambda == Approx(v.lambda).epsilon(1e-14));
        CHECK(cell.production == Approx(v.eta * g * g).epsilon(1e-14));
        CHECK(cell.sinkRate * T == Approx(v.epsR * v.pK).epsilon(1e-14));
        // For c > 0: eta = eta0 p/s and eps_r p_k = eps0 p s, s = sqrt(T g_c) (GranularTemperatureModel.hpp).
        const double s = std::sqrt(T * v.gc), q = p / 1060.0;
        CHECK(v.eta == Approx(lac.eta0 * q / s).epsilon(1e-12));
        CHECK(cell.dissipation == Approx(lac.eps0 * q * s).epsilon(1e-12));
    }
    SECTION("at rest (T at its floor) the cap sets eta and scales lambda by the same factor") {
        const auto cell = model.evaluate(1000.0, 1e-12, 0.2);
        const auto v = lactose().values(cell.c, 1e-12);
        REQUIRE(cell.capped);
        CHECK(cell.eta == Approx(1e3).epsilon(1e-14));
        CHECK(cell.lambda * 1060.0 / cell.eta == Approx(lac.lambda0 / lac.eta0).epsilon(1e-12));
        CHECK(cell.production == Approx(1e3 / 1060.0 * 0.2 * 0.2).epsilon(1e-14));
        CHECK(cell.dissipation == Approx(v.epsR * v.pK).epsilon(1e-14));  // not capped
    }
    SECTION("zero or negative pressure: no powder contact, c = 0 and no stress, heating or dissipation") {
        for (double p : {0.0, -300.0}) {
            const auto cell = model.evaluate(p, 1e-6, 5.0);
            CHECK(cell.c == 0.0);
            CHECK(cell.eta == 0.0);
            CHECK(cell.lambda == 0.0);
            CHECK(cell.production == 0.0);
            CHECK(cell.sinkRate == 0.0);
        }
    }
    SECTION("bad state and parameters, naming the value or key") {
        CHECK_THROWS_WITH(model.evaluate(100.0, 1e-6, -1.0), Contains("shear rate -1 1/s"));
        CHECK_THROWS_WITH(model.evaluate(100.0, 0.0, 1.0), Contains("granular temperature T = 0"));
        CHECK_THROWS_WITH(model.evaluate(NAN, 1e-6, 1.0), Contains("pressure per particle density q = nan"));
        const std::string base =
            "type latzSchmidt; c0 0.5579; cMax 0.5771; T0 0.41; eta0 0.00052; lambda0 0.001; eps0 332.84;";
        CHECK_THROWS_WITH(GranularTemperatureModel::fromDictionary(Dictionary::fromString(base, "props")),
                          Contains("key 'rhoP': missing"));
        CHECK_THROWS_WITH(
            GranularTemperatureModel::fromDictionary(Dictionary::fromString(base + " rhoP 1060; TMin 0;", "props")),
            Contains("file 'props', key 'TMin'") && Contains("TMin = 0"));
        // The closure comes from the rheology registry: its own key errors, and any other rheology, are named.
        CHECK_THROWS_WITH(GranularTemperatureModel::fromDictionary(
                              Dictionary::fromString(
                                  "type latzSchmidt; c0 0.5579; cMax 0.5771; T0 0.41; eta0 0.00052; lambda0 0.001;"
                                  " eps0 -1; rhoP 1060;",
                                  "props")),
                          Contains("file 'props', key 'eps0'") && Contains("eps0 = -1"));
        CHECK_THROWS_WITH(GranularTemperatureModel::fromDictionary(Dictionary::fromString(
                              "type muI; muS 0.4; mu2 0.9; I0 0.05; d 1e-3; rhoP 1060;", "props")),
                          Contains("file 'props', key 'type'") && Contains("needs rheology 'latzSchmidt', got 'muI'"));
        CHECK_NOTHROW(GranularTemperatureModel::fromDictionary(Dictionary::fromString(base + " rhoP 1060;", "props")));
    }
}
