// Limits of the rheologies: mu(I) between mu_s and mu_2, the Coulomb stress
// |tau| = mu p, the numerical cap and floors, dilatancy, the well-posedness
// of the Barker & Gray (2017) regularisation, and the latzSchmidt limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/Dictionary.hpp"
#include "rheology/LatzSchmidt.hpp"
#include "rheology/MuI.hpp"

using granair::Dictionary;
using granair::LatzSchmidt;
using granair::MuI;

namespace {

// MCC spheres (Remmelgas et al. 2019) with explicit numerical limits.
const std::string mcc =
    "type muI; muS 0.401; mu2 0.908; I0 0.0465; d 660e-6; rhoP 1500;"
    "etaMax 1e5; gammaDotMin 1e-6;";

std::unique_ptr<granair::Rheology> create(const std::string& text) {
    return granair::rheologies().create(Dictionary::fromString(text, "test"));
}
const MuI& asMuI(const std::unique_ptr<granair::Rheology>& r) { return dynamic_cast<const MuI&>(*r); }

// Lactose (reference case A).
LatzSchmidt lactose() { return LatzSchmidt({0.5579, 0.5771, 0.41, 0.00052, 0.001, 332.84}); }

}  // namespace

TEST_CASE("rheology muI: limits", "[rheology][muI]") {
    const auto r = create(mcc);
    const MuI& m = asMuI(r);

    SECTION("mu(I) runs from mu_s at I -> 0 to mu_2 at I -> infinity") {
        CHECK(m.friction(0.0) == 0.401);
        // mu - mu_s = (mu_2 - mu_s) I/(I0 + I) ~ 1.1e-11 at I = 1e-12.
        CHECK(std::abs(m.friction(1e-12) - 0.401) < 2e-11);
        // mu_2 - mu = (mu_2 - mu_s) I0/(I0 + I) ~ 2.4e-14 at I = 1e12.
        CHECK(std::abs(m.friction(1e12) - 0.908) < 1e-13);
        // At I = I0 the friction is halfway between the limits (Jop form).
        CHECK(m.friction(0.0465) == Approx(0.5 * (0.401 + 0.908)).epsilon(1e-14));
        // Monotonic between.
        double last = 0;
        for (double I = 1e-8; I < 1e4; I *= 3) {
            CHECK(m.friction(I) > last);
            last = m.friction(I);
        }
    }

    SECTION("below the cap the stress magnitude eta gammaDot is mu(I) p (Coulomb)") {
        for (double p : {20.0, 300.0, 1500.0})
            for (double g : {0.05, 1.0, 40.0}) {
                const double I = m.inertialNumber(p, g);
                CHECK(I == Approx(g * 660e-6 / std::sqrt(p / 1500.0)).epsilon(1e-14));
                CHECK(m.viscosity(p, g) * g == Approx(m.friction(I) * p).epsilon(1e-14));
            }
    }

    SECTION("the viscosity cap, the viscosity floor and the shear-rate floor are active where documented") {
        // 0.401 * 1000 / 1e-3 = 4e5 Pa s > etaMax.
        CHECK(m.viscosity(1000.0, 1e-3) == 1e5);
        CHECK(m.viscosity(1000.0, 1.0) < 1e5);
        // Default floor rho_p d sqrt(g d) = 1500 * 660e-6 * sqrt(9.81 * 660e-6) = 0.07966 Pa s.
        const double etaMin = 1500.0 * 660e-6 * std::sqrt(9.81 * 660e-6);
        CHECK(m.parameters().etaMin == Approx(etaMin).epsilon(1e-15));
        CHECK(etaMin == Approx(0.0796602).epsilon(1e-6));
        // Near the free surface (small p, fast shear) mu p/gammaDot falls below it.
        CHECK(m.viscosity(0.2, 5.0) == etaMin);
        CHECK(m.viscosity(5.0, 200.0) == etaMin);
        CHECK(m.viscosity(40.0, 60.0) > etaMin);
        // gammaDot = 0 behaves as gammaDotMin: finite I, capped viscosity.
        CHECK(m.inertialNumber(800.0, 0.0) == m.inertialNumber(800.0, 1e-6));
        CHECK(m.viscosity(800.0, 0.0) == 1e5);
        // An explicit floor replaces the default.
        const auto r2 = create(mcc + "etaMin 0.5;");
        CHECK(asMuI(r2).viscosity(0.2, 5.0) == 0.5);
    }

    SECTION("no tension: p <= 0 is stress-free at etaMin, with no pressure floor") {
        const double etaMin = m.parameters().etaMin;
        for (double p : {0.0, -1e-9, -250.0, -7e3}) {
            INFO("p = " << p);
            CHECK(m.viscosity(p, 2.0) == etaMin);
            CHECK(m.viscosity(p, 0.0) == etaMin);  // not the cap: no contact stress at rest either
            CHECK(std::isinf(m.inertialNumber(p, 2.0)));
            CHECK(m.solidFraction(p, 2.0) == 0.443);
        }
        CHECK(m.friction(INFINITY) == 0.908);
        // A small positive pressure is not floored: the Coulomb stress mu p follows p down to zero.
        CHECK(m.viscosity(1e-3, 1e-6) * 1e-6 == Approx(m.friction(m.inertialNumber(1e-3, 1e-6)) * 1e-3).epsilon(1e-14));
        // Every output of evaluate() is defined (I infinite, the others finite).
        granair::GranularState s;
        s.p = -10.0;
        s.gammaDot = 3.0;
        const auto v = r->evaluate(s);
        CHECK(std::isinf(v[0]));
        CHECK(v[1] == 0.908);
        CHECK(v[2] == etaMin);
        CHECK(v[3] == 0.443);
    }

    SECTION("dilatancy phi(I) is linear and clamped to [phi_min, phi_max]") {
        CHECK(m.dilatancy(0.0) == 0.632);
        CHECK(m.dilatancy(0.5) == Approx(0.5 * (0.632 + 0.443)).epsilon(1e-14));
        CHECK(m.dilatancy(1.0) == Approx(0.443).epsilon(1e-14));
        CHECK(m.dilatancy(7.0) == 0.443);
        CHECK(m.solidFraction(1000.0, 10.0) == m.dilatancy(m.inertialNumber(1000.0, 10.0)));
    }

    SECTION("analytic d mu/dI matches a central difference, for both forms") {
        const auto reg = create(mcc + "regularisation barkerGray2017;");
        for (const MuI* law : {&m, &asMuI(reg)})
            for (double I : {1e-7, 1e-4, 1e-3, 5e-3, 0.05, 0.8, 20.0}) {
                // h = 1e-4 I: truncation ~1e-8 and round-off ~1e-16 mu/(2h mu') ~1e-7
                // relative, so 1e-6 separates a wrong derivative from the FD error.
                const double h = 1e-4 * I;
                const double fd = (law->friction(I + h) - law->friction(I - h)) / (2 * h);
                INFO("I = " << I);
                CHECK(law->frictionDerivative(I) == Approx(fd).epsilon(1e-6));
            }
    }
}

TEST_CASE("rheology muI: well-posedness (Barker et al. 2015) and the barkerGray2017 regularisation",
          "[rheology][muI]") {
    const auto jopR = create(mcc);
    const auto regR = create(mcc + "regularisation barkerGray2017; alphaReg 1.9; muInf 0.05;");
    const MuI& jop = asMuI(jopR);
    const MuI& reg = asMuI(regR);

    SECTION("the Jop form is ill posed at low and high I and well posed between (MCC roots as documented)") {
        // Roots of C(I) for MCC, computed independently (python bisection): 1.8409e-3 and 0.10589.
        CHECK(jop.illPosedness(1e-6) > 0);
        CHECK(jop.illPosedness(1.83e-3) > 0);
        CHECK(jop.illPosedness(1.85e-3) < 0);
        CHECK(jop.illPosedness(0.02) < 0);
        CHECK(jop.illPosedness(0.105) < 0);
        CHECK(jop.illPosedness(0.107) > 0);
        CHECK(jop.illPosedness(10.0) > 0);
        // C(I1) = 0 at the regularisation's switch point.
        CHECK(std::abs(jop.illPosedness(reg.regularisationI1())) < 1e-12);
    }

    SECTION("barkerGray2017 is continuous at I1 and well posed for every I below the high-I limit") {
        const double i1 = reg.regularisationI1();
        CHECK(i1 == Approx(1.8409061842688745e-3).epsilon(1e-9));
        CHECK(reg.friction(i1 * (1 - 1e-12)) == Approx(reg.friction(i1)).epsilon(1e-10));
        for (double I = 1e-14; I < 0.109; I *= 1.1) {
            INFO("I = " << I << ", C = " << reg.illPosedness(I));
            CHECK(reg.illPosedness(I) < 0);
        }
    }

    SECTION("what barkerGray2017 does not fix: high I stays ill posed; low-I friction falls below mu_s") {
        CHECK(reg.illPosedness(0.111) > 0);
        CHECK(reg.illPosedness(1.0) > 0);
        CHECK(reg.friction(1e-6) < 0.401);
        CHECK(reg.friction(1e-6) == Approx(0.3224565).epsilon(1e-6));
        CHECK(reg.friction(0.0) == 0.0);
    }
}

TEST_CASE("rheology latzSchmidt: limits", "[rheology][latzSchmidt]") {
    const LatzSchmidt ls = lactose();

    SECTION("tan(phi) = sqrt(eta0 eps0) of the calibration") {
        CHECK(ls.tanFrictionAngle() == Approx(std::sqrt(0.00052 * 332.84)).epsilon(1e-15));
        CHECK(std::atan(ls.tanFrictionAngle()) * 180 / M_PI == Approx(22.5885).epsilon(1e-5));
    }

    SECTION("below c0 the closure is purely kinetic: p = c T g_c, no yield pressure") {
        const auto v = ls.values(0.4, 0.3);
        CHECK(v.pY == 0.0);
        CHECK(v.p == Approx(0.4 * 0.3 / (1 - 0.4 / 0.5771)).epsilon(1e-14));
        // Kinetic scaling: at fixed c, eta, lambda, eps_r grow like sqrt(T).
        const auto w = ls.values(0.4, 1.2);
        CHECK(w.eta / v.eta == Approx(2.0).epsilon(1e-14));
        CHECK(w.lambda / v.lambda == Approx(2.0).epsilon(1e-14));
        CHECK(w.epsR / v.epsR == Approx(2.0).epsilon(1e-14));
    }

    SECTION("above c0, as T -> 0: p -> p_y finite, eta -> infinity like 1/sqrt(T) (yield stress)") {
        // p_k/p_y = c T/(T0 (c - c0)) ~ 1.1e-4 T/1e-6, so at T = 1e-8 and 1e-10
        // the plastic part dominates to ~1e-6 and ~1e-8.
        const auto a = ls.values(0.57, 1e-8);
        const auto b = ls.values(0.57, 1e-10);
        const double pY = 0.41 * (0.57 - 0.5579) / (1 - 0.57 / 0.5771);
        CHECK(a.pY == Approx(pY).epsilon(1e-14));
        CHECK(b.p == Approx(pY).epsilon(1e-6));
        CHECK(b.eta / a.eta == Approx(10.0).epsilon(1e-5));
    }

    SECTION("c = 0 gives no pressure and no viscosity") {
        const auto v = ls.values(0.0, 0.5);
        CHECK(v.p == 0.0);
        CHECK(v.eta == 0.0);
        CHECK(v.lambda == 0.0);
        CHECK(v.epsR == Approx(332.84 * std::sqrt(0.5)).epsilon(1e-14));
    }

    SECTION("g_c diverges as c -> c_max") {
        CHECK(ls.values(0.5771 * (1 - 1e-9), 0.1).gc == Approx(1e9).epsilon(1e-6));
    }
}
