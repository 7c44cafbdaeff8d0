// Limits of the drag laws: creeping flow (Stokes), zero slip, and coarse
// graining of parcels.
#include <catch2/catch.hpp>

#include <cmath>

#include "DragTestSupport.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "drag/DragLaw.hpp"

namespace {

const granair::FluidProperties air{1.2, 1.8e-5};

// One named law with its default parameters (for the law-specific limits).
std::unique_ptr<granair::DragLaw> law(const std::string& name) {
    return granair::dragLaws().create(granair::Dictionary::fromString("type " + name + ";", "test"));
}

// Slip velocity giving Reynolds number Re = rho d eps |u| / mu.
double slipFor(double Re, double d, double eps, const granair::FluidProperties& f) {
    return Re * f.mu / (f.rho * d * eps);
}

}  // namespace

TEST_CASE("drag laws: limits and coarse graining", "[drag][limits]") {
    SECTION("every drag law is finite and positive at zero slip") {
        // At |u| = 0 each law must return its creeping-flow limit, never NaN
        // (Cd ~ 1/Re and |u| -> 0 cancel analytically in each implementation).
        for (const auto& name : granair::dragLaws().names()) {
            auto l = dragtest::lawFromData(name);
            for (double eps : {0.4, 0.7, 0.85, 1.0}) {
                const double beta = l->beta(1e-4, eps, 0.0, air);
                INFO(name << " at eps = " << eps << ": beta(slip = 0) = " << beta);
                CHECK(std::isfinite(beta));
                CHECK(beta > 0);
                // Continuous into zero slip: a tiny slip (Re ~ 1e-12) changes beta by < 1e-4.
                CHECK(l->beta(1e-4, eps, slipFor(1e-12, 1e-4, eps, air), air) == Approx(beta).epsilon(1e-4));
            }
        }
    }

    SECTION("SchillerNaumann tends to Stokes drag 3 pi mu d") {
        auto l = law("SchillerNaumann");
        const double d = 1e-4;
        const double stokes = 3 * M_PI * air.mu * d;
        // Exactly Stokes at zero slip (Cd Re = 24).
        CHECK(l->beta(d, 1.0, 0.0, air) == Approx(stokes).epsilon(1e-14));
        // At Re = 1e-6 the correction is 0.15 Re^0.687 = 1.17e-5: tolerance 2e-5.
        CHECK(l->beta(d, 1.0, slipFor(1e-6, d, 1.0, air), air) == Approx(stokes).epsilon(2e-5));
    }

    SECTION("DiFelice at eps = 1 tends to Dallavalle's creeping drag, 0.96 x Stokes") {
        // Dallavalle's Cd = (0.63 + 4.8/sqrt(Re))^2 -> 23.04/Re, so the creeping
        // limit is (pi/8) 23.04 mu d = 2.88 pi mu d = 0.96 x Stokes: within 4 % of
        // Stokes by construction of the correlation.
        auto l = law("DiFelice");
        const double d = 1e-4;
        const double stokes = 3 * M_PI * air.mu * d;
        const double limit = 2.88 * M_PI * air.mu * d;
        CHECK(l->beta(d, 1.0, 0.0, air) == Approx(limit).epsilon(1e-14));
        // At Re = 1e-6: (0.63 sqrt(Re) + 4.8)^2/23.04 - 1 = 2.6e-4; tolerance 3e-4.
        const double beta = l->beta(d, 1.0, slipFor(1e-6, d, 1.0, air), air);
        CHECK(beta == Approx(limit).epsilon(3e-4));
        CHECK(std::abs(beta / stokes - 1.0) < 0.041);
        // Away from eps = 1 the creeping limit carries eps^(1 - 3.7).
        CHECK(l->beta(d, 0.5, 0.0, air) == Approx(limit * std::pow(0.5, -2.7)).epsilon(1e-14));
    }

    SECTION("WenYu and BVK tend to Stokes drag for a single sphere in creeping flow") {
        const double d = 1e-4;
        const double stokes = 3 * M_PI * air.mu * d;
        // Wen-Yu: 3 pi mu d eps^-2.65 at zero slip.
        CHECK(law("WenYu")->beta(d, 1.0, 0.0, air) == Approx(stokes).epsilon(1e-14));
        CHECK(law("WenYu")->beta(d, 0.6, 0.0, air) == Approx(stokes * std::pow(0.6, -2.65)).epsilon(1e-14));
        // BVK: F(phi = 0, Re = 0) = 1 exactly.
        auto bvk = law("BeetstraVanDerHoefKuipers");
        CHECK(bvk->beta(d, 1.0, 0.0, air) == Approx(stokes).epsilon(1e-14));
        // phi = 1e-8, Re = 1e-6: F - 1 = 10 phi + 1.5 sqrt(phi) + O(Re^1.16) ~ 1.5e-4;
        // tolerance 2e-4.
        const double eps = 1 - 1e-8;
        CHECK(bvk->beta(d, eps, slipFor(1e-6, d, eps, air), air) == Approx(stokes).epsilon(2e-4));
    }

    SECTION("parcelBeta: s = 1 is the particle, s = 2 is 8 primary particles") {
        const granair::FluidProperties water{998.2, 1.002e-3};
        for (const auto& name : granair::dragLaws().names()) {
            auto l = dragtest::lawFromData(name);
            for (const auto& f : {air, water}) {
                for (double eps : {0.45, 0.9, 1.0}) {
                    for (double slip : {0.0, 0.05, 2.0}) {
                        const double d = 2e-4;
                        INFO(name << ": eps = " << eps << ", slip = " << slip << ", rho = " << f.rho);
                        CHECK(granair::parcelBeta(*l, d, 1.0, eps, slip, f) == l->beta(d, eps, slip, f));
                        // A parcel of diameter 2d at s = 2 holds 8 primaries of diameter d.
                        CHECK(granair::parcelBeta(*l, 2 * d, 2.0, eps, slip, f) ==
                              Approx(8.0 * l->beta(d, eps, slip, f)).epsilon(1e-14));
                    }
                }
            }
        }
        auto l = law("WenYu");
        CHECK_THROWS_AS(granair::parcelBeta(*l, 1e-3, 0.5, 0.5, 1.0, air), granair::InputError);
        CHECK_THROWS_WITH(granair::parcelBeta(*l, 1e-3, NAN, 0.5, 1.0, air), Catch::Matchers::Contains("nan"));
    }
}
