// Conservation of the CG fields (docs/cg-fields.md, issue 15 "Tests"):
//  - every kernel integrates to 1 in every coordinate system, and total mass,
//    momentum, particle number and volume are reproduced to 1e-10, away from
//    the window's edges;
//  - two spheres in contact: the volume integral of the contact stress is
//    f (x) r_ij to 1e-10 for every kernel and width; a wall contact gives
//    f (x) (x_i - c) and its traction integrates to f.
// Integrals use the nested quadrature of CgQuadrature.hpp on the fields at
// arbitrary points (CoarseGrainer::evaluateAt).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "CgTestSupport.hpp"

using namespace granair;
using namespace granair::cgtest;

namespace {

std::vector<CgParticle> someParticles() {
    std::vector<CgParticle> ps(3);
    ps[0].x = Vec3(0.4e-3, -0.7e-3, 1.1e-3), ps[0].v = Vec3(0.3, -1.2, 0.7), ps[0].mass = 2.1e-6;
    ps[1].x = Vec3(1.3e-3, 0.2e-3, 0.5e-3), ps[1].v = Vec3(-0.8, 0.1, 0.4), ps[1].mass = 1.3e-6;
    ps[2].x = Vec3(-0.6e-3, 1.9e-3, -0.9e-3), ps[2].v = Vec3(0.05, 0.6, -1.5), ps[2].mass = 3.0e-6;
    for (auto& p : ps) p.radius = 0.5e-3;
    return ps;
}

// Breaks at each level for balls of radius c about the given centres (resolved axes ax).
Breaks ballBreaks(const std::vector<Vec3>& centres, const std::vector<int>& ax, double c) {
    return [=](int level, const double* u) {
        std::vector<double> b;
        for (const auto& x : centres) {
            double d2 = 0;
            for (int m = 0; m < level; ++m) d2 += (u[m] - x[ax[m]]) * (u[m] - x[ax[m]]);
            const double h = chord(c, d2);
            if (h <= 0) continue;
            const double x0 = x[ax[level]];
            b.insert(b.end(), {x0 - h, x0, x0 + h});
        }
        return b;
    };
}

}  // namespace

TEST_CASE("CG: every kernel integrates to 1 and mass, momentum are conserved (Cartesian)", "[cg]") {
    const auto ps = someParticles();
    for (const auto& kc : kernelCases())
        for (auto sys : cartesianSystems()) {
            INFO(kc.name << " width " << kc.width << " in " << cgCoordinatesName(sys));
            const auto cg = makeCg(sys, kc, testWindow());
            const auto ax = resolvedAxes(sys);
            const Vec3 mid = 0.5 * (testWindow().lo + testWindow().hi);
            auto toPoint = [&](const double* u) {
                Vec3 p = mid;
                for (std::size_t m = 0; m < ax.size(); ++m) p[ax[m]] = u[m];
                return p;
            };
            for (std::size_t count : {std::size_t(1), ps.size()}) {
                CgSnapshot snap;
                snap.particles.assign(ps.begin(), ps.begin() + count);
                std::vector<Vec3> centres;
                double M = 0, V = 0;
                Vec3 P = Vec3::Zero();
                for (const auto& p : snap.particles) {
                    centres.push_back(p.x);
                    M += p.mass;
                    P += p.mass * p.v;
                    V += M_PI / 6.0 * std::pow(2 * p.radius, 3);
                }
                const auto I = integrateCartesian(cg, snap, ballBreaks(centres, ax, cg.kernel().cutoff()), 24,
                                                  toPoint);
                CHECK(std::abs(I[cgraw::number] / count - 1.0) < 1e-10);
                CHECK(std::abs(I[cgraw::density] / M - 1.0) < 1e-10);
                CHECK(std::abs(I[cgraw::volume] / V - 1.0) < 1e-10);
                double pScale = 0;
                for (const auto& p : snap.particles) pScale += p.mass * p.v.norm();
                for (int a = 0; a < 3; ++a) CHECK(std::abs(I[cgraw::momentum + a] - P[a]) < 1e-10 * pScale);
            }
        }
}

namespace {

// Nested rule over a segment's capsule A -> B in D = 1, 2, 3 resolved axes,
// in a frame along the (projected) segment; returns the raw-field integrals.
std::vector<double> integrateSegment(const CoarseGrainer& cg, const CgSnapshot& snap, const Vec3& A,
                                     const Vec3& B) {
    const auto sys = cg.grid().coordinates();
    const auto ax = resolvedAxes(sys);
    const int D = int(ax.size());
    const double c = cg.kernel().cutoff();
    const Vec3 mid = 0.5 * (testWindow().lo + testWindow().hi);
    if (D == 0) return integrateCartesian(cg, snap, [](int, const double*) { return std::vector<double>{}; }, 1,
                                          [&](const double*) { return mid; });
    // Orthonormal frame of the resolved space with e0 along the projection.
    Vec3 e[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    Vec3 E = Vec3::Zero();
    for (int a : ax) E[a] = B[a] - A[a];
    const double L = E.norm();
    REQUIRE(L > 0);
    e[0] = E / L;
    if (D == 2) {
        e[1][ax[0]] = -e[0][ax[1]];
        e[1][ax[1]] = e[0][ax[0]];
    } else if (D == 3) {
        e[1] = e[0].unitOrthogonal();
        e[2] = e[0].cross(e[1]);
    }
    // Levels: the perpendicular coordinates first (outer), the axial one last.
    const double kink = c * c - 0.25 * L * L;  // where h = L/2: the two end kinks meet
    Breaks breaks = [=](int level, const double* u) {
        double d2 = 0;
        for (int m = 0; m < level; ++m) d2 += u[m] * u[m];
        const double h = chord(c, d2);
        if (level < D - 1) {
            std::vector<double> b{-h, 0.0, h};  // 0: the axis, where Lucy's |x|^3 term is least smooth
            if (kink > d2) {
                // The end kinks meet at +-k; when k lies close to the support's
                // edge h (a short projected segment), grade the pieces towards it.
                const double k = std::sqrt(kink - d2);
                b.insert(b.end(), {-k, k});
                if (h - k < 0.02 * h) addGraded(b, 0.0, k, h - k), addGraded(b, 0.0, -k, h - k);
            }
            return b;
        }
        return std::vector<double>{-h, 0.0, h, L - h, L, L + h};
    };
    auto toPoint = [&](const double* u) {
        Vec3 p = mid;
        Vec3 q = Vec3::Zero();
        for (int a : ax) q[a] = A[a];
        q += u[D - 1] * e[0];
        for (int m = 0; m + 1 < D; ++m) q += u[m] * e[m + 1];
        for (int a : ax) p[a] = q[a];
        return p;
    };
    return integrateCartesian(cg, snap, breaks, D == 3 ? 16 : 24, toPoint);
}

}  // namespace

TEST_CASE("CG: two spheres in contact: the contact stress integrates to f (x) r_ij", "[cg]") {
    CgSnapshot snap;
    CgPairContact c;
    c.xi = Vec3(0.3e-3, -0.2e-3, 0.1e-3);
    c.xj = c.xi - Vec3(0.62e-3, 0.41e-3, 0.65e-3);  // |r_ij| = 0.985 mm: touching 0.5 mm spheres
    c.force = Vec3(1.7, 0.9, 2.3);
    snap.pairs.push_back(c);
    const Vec3 r = c.xi - c.xj;
    for (const auto& kc : kernelCases())
        for (auto sys : cartesianSystems()) {
            INFO(kc.name << " width " << kc.width << " in " << cgCoordinatesName(sys));
            const auto cg = makeCg(sys, kc, testWindow());
            const auto I = integrateSegment(cg, snap, c.xi, c.xj);
            const double scale = c.force.norm() * r.norm();
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    CHECK(std::abs(I[cgraw::contactStress + 3 * a + b] - c.force[a] * r[b]) < 1e-10 * scale);
        }
}

TEST_CASE("CG: a wall contact integrates to f (x) (x - c), its traction to f", "[cg]") {
    CgSnapshot snap;
    CgWallContact w;
    w.x = Vec3(0.2e-3, 0.1e-3, 0.5e-3);
    w.point = Vec3(0.25e-3, 0.05e-3, 0.02e-3);  // a sloping wall below
    w.force = Vec3(0.2, -0.1, 3.1);
    snap.walls.push_back(w);
    const Vec3 b = w.x - w.point;
    for (const auto& kc : kernelCases())
        for (auto sys : cartesianSystems()) {
            INFO(kc.name << " width " << kc.width << " in " << cgCoordinatesName(sys));
            const auto cg = makeCg(sys, kc, testWindow());
            const auto I = integrateSegment(cg, snap, w.x, w.point);
            const double scale = w.force.norm() * b.norm();
            for (int a = 0; a < 3; ++a) {
                CHECK(std::abs(I[cgraw::wallForce + a] - w.force[a]) < 1e-10 * w.force.norm());
                for (int k = 0; k < 3; ++k)
                    CHECK(std::abs(I[cgraw::contactStress + 3 * a + k] - w.force[a] * b[k]) < 1e-10 * scale);
            }
        }
}
