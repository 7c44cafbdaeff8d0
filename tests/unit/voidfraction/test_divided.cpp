// The divided model: its point layout (equal volumes, a spherical 5-design)
// and how well it splits a sphere between cells, against exact geometry.
#include <catch2/catch.hpp>
#include <cmath>

#include "VoidFractionTestSupport.hpp"
#include "mapping/BoxMesh.hpp"
#include "voidfraction/DividedVoidFraction.hpp"

using granair::BoxMesh;
using granair::CellWeight;
using granair::DividedVoidFraction;
using granair::ParticleState;
using granair::Vec3;

namespace {

ParticleState particleAt(const Vec3& x, double r) {
    ParticleState p;
    p.id = 1;
    p.x = x;
    p.radius = r;
    return p;
}

std::vector<CellWeight> stencilOf(const granair::VoidFractionModel& m, const granair::CellLocator& mesh,
                                  const ParticleState& p) {
    std::vector<CellWeight> st;
    const int c = mesh.findCell(p.x);
    REQUIRE(c >= 0);
    m.stencil(mesh, p, c, st);
    vftest::checkStencil(mesh, st);
    return st;
}

// Volume fraction of a unit sphere beyond a plane at distance d (0 <= d <= 1)
// from its centre: the spherical cap, V_cap = pi h^2 (3 - h)/3 with h = 1 - d.
double capFraction(double d) { return d >= 1 ? 0.0 : (1 - d) * (1 - d) * (2 + d) / 4; }

}  // namespace

// Sections of one test case: each ctest test pays ~0.5 s of MPI start-up.
TEST_CASE("divided void-fraction model", "[voidfraction][divided]") {
    SECTION("divided points: N = 1 + 24 shells, inside the sphere, centroid and moments of the sphere") {
        vftest::Random rnd(3);
        for (int shells = 1; shells <= DividedVoidFraction::maxShells; ++shells) {
            INFO("shells " << shells);
            const DividedVoidFraction m(shells);
            const int n = m.nPoints();
            REQUIRE(n == 1 + 24 * shells);
            REQUIRE(m.points()[0].norm() == 0);
            Vec3 centroid = Vec3::Zero();
            double second = 0;
            for (const Vec3& x : m.points()) {
                CHECK(x.norm() < 1);
                centroid += x / n;
                second += x.squaredNorm() / n;
            }
            // Sphere centroid: 0. Second moment of the unit ball: 3/5; the centre
            // point stands for the inner ball of radius N^(-1/3), whose 3/5 N^(-5/3)
            // it drops (each shell keeps its own exactly). Round-off: 1e-14.
            CHECK(centroid.norm() < 1e-14);
            CHECK(second == Approx(0.6 * (1 - std::pow(n, -5.0 / 3.0))).epsilon(1e-14));
            // Each shell's 24 directions form a spherical 5-design: for any unit n,
            // the mean of (n.u)^k equals the sphere average, 1/3 (k = 2), 1/5 (k = 4),
            // 0 (k odd) (e.g. Delsarte, Goethals, Seidel 1977, Geom. Dedicata 6:363).
            for (int trial = 0; trial < 10; ++trial) {
                Vec3 dir(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1));
                dir.normalize();
                for (int s = 0; s < shells; ++s) {
                    double m1 = 0, m2 = 0, m3 = 0, m4 = 0, m5 = 0;
                    const double rk = m.points()[1 + 24 * s].norm();
                    for (int i = 0; i < 24; ++i) {
                        const Vec3& x = m.points()[1 + 24 * s + i];
                        CHECK(x.norm() == Approx(rk).epsilon(1e-14));
                        const double t = dir.dot(x) / rk;
                        m1 += t / 24, m2 += t * t / 24, m3 += t * t * t / 24, m4 += t * t * t * t / 24;
                        m5 += std::pow(t, 5) / 24;
                    }
                    CHECK(std::abs(m1) < 1e-14);
                    CHECK(m2 == Approx(1.0 / 3).epsilon(1e-13));
                    CHECK(std::abs(m3) < 1e-14);
                    CHECK(m4 == Approx(1.0 / 5).epsilon(1e-13));
                    CHECK(std::abs(m5) < 1e-14);
                }
            }
        }
    }

    SECTION("a particle inside one cell stays there and one on a face, edge or corner splits evenly") {
        for (int shells = 1; shells <= DividedVoidFraction::maxShells; ++shells) {
            const DividedVoidFraction m(shells);
            const double n = m.nPoints();
            INFO("shells " << shells << ", N = " << n);
            // Unit cells; particle radius 0.3 (so it reaches only the cells that meet
            // at its centre).
            {
                const BoxMesh mesh(Vec3(0, 0, 0), Vec3(2, 1, 1), {2, 1, 1});
                const auto inside = stencilOf(m, mesh, particleAt(Vec3(0.5, 0.5, 0.5), 0.3));
                REQUIRE(inside.size() == 1);
                CHECK(inside[0].weight == 1.0);
                // On the face x = 1. Exact overlap 1/2 each side. The shells split
                // exactly by reflection symmetry; the centre point (1/N) goes to the
                // upper cell (half-open cells), so each side is within 1/(2N).
                const auto face = stencilOf(m, mesh, particleAt(Vec3(1, 0.5, 0.5), 0.3));
                REQUIRE(face.size() == 2);
                for (int c = 0; c < 2; ++c)
                    CHECK(vftest::weightOf(face, c) == Approx(0.5).margin(0.5 / n + 1e-12));
            }
            {
                // On the edge x = y = 1 of 4 cells: exact 1/4 each; within 1/N.
                const BoxMesh mesh(Vec3(0, 0, 0), Vec3(2, 2, 1), {2, 2, 1});
                const auto edge = stencilOf(m, mesh, particleAt(Vec3(1, 1, 0.5), 0.3));
                REQUIRE(edge.size() == 4);
                for (int c = 0; c < 4; ++c) CHECK(vftest::weightOf(edge, c) == Approx(0.25).margin(1 / n));
            }
            {
                // On the corner of 8 cells: exact 1/8 each; within 1/N.
                const BoxMesh mesh(Vec3(0, 0, 0), Vec3(2, 2, 2), {2, 2, 2});
                const auto corner = stencilOf(m, mesh, particleAt(Vec3(1, 1, 1), 0.3));
                REQUIRE(corner.size() == 8);
                for (int c = 0; c < 8; ++c) CHECK(vftest::weightOf(corner, c) == Approx(0.125).margin(1 / n));
            }
        }
    }

    SECTION("the share across a face follows the spherical-cap volume") {
        // Particle of radius 0.4 at distance d*r below the face between two unit
        // cells, for each axis. Exact share beyond the face: the cap fraction
        // (1-d)^2 (2+d)/4. The 25-point stencil moves in steps of 4/25 (each of the
        // 6 projections of the shell on an axis holds 4 points), so we allow one
        // step, 4/N = 0.16; the largest error over this sweep is 0.13.
        const DividedVoidFraction m(1);
        const double tol = 4.0 / m.nPoints();
        for (int axis = 0; axis < 3; ++axis) {
            BoxMesh::Index3 cells{1, 1, 1};
            cells[axis] = 2;
            Vec3 hi(1, 1, 1);
            hi[axis] = 2;
            const BoxMesh mesh(Vec3(0, 0, 0), hi, cells);
            for (int i = 0; i <= 20; ++i) {
                const double d = i / 20.0, r = 0.4;
                Vec3 x(0.5, 0.5, 0.5);
                x[axis] = 1 - d * r;
                const auto st = stencilOf(m, mesh, particleAt(x, r));
                INFO("axis " << axis << ", d = " << d);
                CHECK(vftest::weightOf(st, 1) == Approx(capFraction(d)).margin(tol));
            }
        }
    }

    SECTION("divided on a decomposed mesh: points on other ranks count for the centre cell") {
        // Compare each particle's stencil on a block with its stencil on the whole
        // mesh: every owned cell keeps its weight, and the centre cell gains exactly
        // the weights of the cells the block does not own. Round-off: 1e-14.
        const Vec3 lo(0, 0, 0), hi(1, 1, 1);
        const BoxMesh::Index3 n{16, 16, 16};
        const BoxMesh whole(lo, hi, n);
        const BoxMesh block(lo, hi, n, {4, 4, 4}, {10, 12, 9});
        const DividedVoidFraction m(2);
        vftest::Random rnd(11);
        const granair::Box b = block.bounds();
        int crossing = 0;
        for (int i = 0; i < 200; ++i) {
            const auto p = particleAt(Vec3(rnd.uniform(b.lo.x(), b.hi.x()), rnd.uniform(b.lo.y(), b.hi.y()),
                                           rnd.uniform(b.lo.z(), b.hi.z())),
                                      rnd.uniform(0.01, 0.1));
            const auto full = stencilOf(m, whole, p);
            const auto part = stencilOf(m, block, p);
            const int centre = block.findCell(p.x);
            const long centreGlobal = block.globalIndex(centre);
            double lost = 0;
            for (const auto& cw : full) {
                const int local = block.localCell(whole.globalIjk(cw.cell));
                if (local < 0)
                    lost += cw.weight;
                else if (whole.globalIndex(cw.cell) != centreGlobal)
                    CHECK(vftest::weightOf(part, local) == Approx(cw.weight).margin(1e-14));
            }
            crossing += lost > 0;
            CHECK(vftest::weightOf(part, centre) ==
                  Approx(vftest::weightOf(full, whole.findCell(p.x)) + lost).margin(1e-14));
        }
        CHECK(crossing > 10);  // the sample does exercise the block boundary
    }

    SECTION("divided parameters: shells is an integer 1..4, errors name the file and key") {
        const auto& reg = granair::voidFractionModels();
        auto make = [&](const std::string& text) {
            return reg.create(granair::Dictionary::fromString(text, "constant/couplingProperties"));
        };
        CHECK(dynamic_cast<const DividedVoidFraction&>(*make("type divided;")).nPoints() == 25);
        CHECK(dynamic_cast<const DividedVoidFraction&>(*make("type divided; shells 3;")).nPoints() == 73);
        for (const char* bad : {"type divided; shells 0;", "type divided; shells 5;",
                                "type divided; shells two;", "type divided; shells 1.5;"}) {
            INFO(bad);
            CHECK_THROWS_AS(make(bad), granair::InputError);
            CHECK_THROWS_WITH(make(bad), Catch::Matchers::Contains("constant/couplingProperties") &&
                                             Catch::Matchers::Contains("shells"));
        }
    }
}
