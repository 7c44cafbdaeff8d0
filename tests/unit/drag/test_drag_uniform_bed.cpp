// Fixed uniform beds: in model A the drag laws plus the separate
// pressure-gradient force must carry the packed-bed pressure drop.
//
// Particles at rest in a bed of void fraction eps, air flowing at superficial
// velocity U (interstitial u = U/eps). The steady fluid momentum balance of
// model A is  eps dp/dx = K u  with K = sum(beta_p)/V_bed, and the total force
// the fluid puts on the particles is  sum(beta_p u) + sum(V_p dp/dx)
// (drag + pressure-gradient force). Per bed volume that total must equal the
// pressure drop of the correlation the law is built on.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/Dictionary.hpp"
#include "drag/BeetstraVanDerHoefKuipers.hpp"
#include "drag/DragLaw.hpp"

namespace {

struct BedForces {
    double totalPerVolume;  // [N/m3] drag + pressure-gradient force, per bed volume
    double dpdx;            // [Pa/m] from the model-A fluid momentum balance
};

// A bed of n identical particles at rest, fluid moving along x at u = U/eps.
BedForces fixedBed(const granair::DragLaw& law, double d, double eps, double U, const granair::FluidProperties& f,
                   int n = 64) {
    const double Vp = M_PI * d * d * d / 6.0;
    const double Vbed = n * Vp / (1.0 - eps);
    const granair::Vec3 Uf(U / eps, 0, 0), Up = granair::Vec3::Zero();
    double sumBeta = 0;
    granair::Vec3 drag = granair::Vec3::Zero();
    for (int i = 0; i < n; ++i) {
        sumBeta += law.beta(d, eps, (Uf - Up).norm(), f);
        drag += law.force(d, eps, Uf, Up, f);
    }
    const double K = sumBeta / Vbed;
    const double dpdx = K * Uf.x() / eps;        // eps dp/dx = K u
    const double pressureForce = n * Vp * dpdx;  // sum of V_p dp/dx
    return {(drag.x() + pressureForce) / Vbed, dpdx};
}

}  // namespace

TEST_CASE("drag laws: fixed uniform beds", "[drag][bed]") {
    SECTION("ErgunGidaspow: a fixed bed carries exactly the Ergun pressure drop") {
        auto law = granair::dragLaws().create(granair::Dictionary::fromString("type ErgunGidaspow;", "test"));
        const double eps = 0.4;  // below the 0.8 switch: Ergun branch
        const std::vector<granair::FluidProperties> fluids = {{1.2, 1.8e-5}, {998.2, 1.002e-3}};  // air, water
        for (double d : {225e-6, 2e-3}) {
            for (const auto& f : fluids) {
                // Particle Reynolds number on the superficial velocity, 0.1 .. 100.
                for (double Re : {0.1, 1.0, 10.0, 100.0}) {
                    const double U = Re * f.mu / (f.rho * d);
                    const auto bed = fixedBed(*law, d, eps, U, f);
                    // Ergun (1952): dp/dx = 150 mu U (1-eps)^2/(eps^3 d^2) + 1.75 rho U^2 (1-eps)/(eps^3 d)
                    const double ergun = 150.0 * f.mu * U * (1 - eps) * (1 - eps) / (eps * eps * eps * d * d) +
                                         1.75 * f.rho * U * U * (1 - eps) / (eps * eps * eps * d);
                    INFO("d = " << d << " m, rho = " << f.rho << ", Re = " << Re << ", U = " << U
                                << " m/s: total force / V = " << bed.totalPerVolume << " N/m3, Ergun " << ergun);
                    // Round-off only (the law is Ergun's, rearranged per particle).
                    CHECK(bed.totalPerVolume == Approx(ergun).epsilon(1e-12));
                    CHECK(bed.dpdx == Approx(ergun).epsilon(1e-12));
                }
            }
        }
    }

    SECTION("BeetstraVanDerHoefKuipers: normalisation reproduces Carman-Kozeny in creeping flow") {
        // At Re -> 0 the BVK drag is F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi)); the
        // first term was fitted to Carman-Kozeny, dp/dx = 180 mu U phi^2/(eps^3 d^2).
        // With beta = 3 pi mu d eps F (drag only, pressure-gradient force added
        // separately) the bed pressure drop is therefore CK times
        //     1 + eps^4 (1 + 1.5 sqrt(phi)) / (10 phi),
        // i.e. within 1 % at phi = 0.6. A wrong normalisation (using BVK as the
        // total force, or dividing by eps) would be off by 1/eps = 2.5 here.
        const granair::BeetstraVanDerHoefKuipers law;
        const granair::FluidProperties air{1.2, 1.8e-5};
        const double d = 1e-4;
        for (double eps : {0.4, 0.5}) {
            const double phi = 1 - eps;
            const double U = 1e-3;  // only sets the scale: beta is evaluated in the creeping limit below
            // beta at zero slip is the creeping-flow (Re = 0) coefficient.
            const double beta0 = law.beta(d, eps, 0.0, air);
            const double n = phi / (M_PI * d * d * d / 6.0);
            const double dpdx = n * beta0 * (U / eps) / eps;  // eps dp/dx = K u
            const double carmanKozeny = 180.0 * air.mu * U * phi * phi / (eps * eps * eps * d * d);
            const double expectedRatio = 1.0 + std::pow(eps, 4) * (1.0 + 1.5 * std::sqrt(phi)) / (10.0 * phi);
            INFO("eps = " << eps << ": dp/dx = " << dpdx << " Pa/m, Carman-Kozeny " << carmanKozeny);
            CHECK(dpdx / carmanKozeny == Approx(expectedRatio).epsilon(1e-12));
            if (eps == 0.4) CHECK(std::abs(dpdx / carmanKozeny - 1.0) < 0.01);
            // And the same through the fixed-bed force balance at a tiny Re (1e-9):
            // the inertial correction is O(Re^0.657 ...) and far below 1e-6.
            const double Utiny = 1e-9 * air.mu / (air.rho * d);
            const auto bed = fixedBed(law, d, eps, Utiny, air);
            const double ckTiny = 180.0 * air.mu * Utiny * phi * phi / (eps * eps * eps * d * d);
            CHECK(bed.totalPerVolume / ckTiny == Approx(expectedRatio).epsilon(1e-6));
        }
    }
}
