// The snapshot loop (CoarseGrainer::compute): the grid fields equal the
// fields evaluated point by point, whatever the thread count (bitwise);
// periodic directions wrap; the window clips what lies outside it along
// averaged directions; bad grids are refused with clear messages.
#include <catch2/catch.hpp>

#include <random>

#include "CgTestSupport.hpp"
#include "cg/CgAverager.hpp"
#include "core/Error.hpp"

using namespace granair;
using namespace granair::cgtest;

namespace {

constexpr double L = 10e-3;

// Particles, pairs (some across the periodic x and y boundaries) and floor contacts.
CgSnapshot randomSnapshot(unsigned seed, const Vec3& shift = Vec3::Zero()) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    CgSnapshot s;
    s.domain.box = Box{Vec3::Zero(), Vec3::Constant(L)};
    s.domain.periodic = {{true, true, false}};
    auto wrap = [&](Vec3 x) {
        for (int a = 0; a < 2; ++a) x[a] -= L * std::floor(x[a] / L);
        return x;
    };
    for (int i = 0; i < 60; ++i) {
        CgParticle p;
        p.id = i + 1;
        p.x = wrap(Vec3(U(rng) * L, U(rng) * L, 0.5e-3 + U(rng) * 9e-3) + shift);
        p.v = Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
        p.omega = Vec3(U(rng), U(rng), U(rng)) * 10.0;
        p.radius = 0.4e-3 + 0.2e-3 * U(rng);
        p.mass = 2500 * 4.0 / 3.0 * M_PI * std::pow(p.radius, 3);
        s.particles.push_back(p);
    }
    for (int i = 0; i < 40; ++i) {
        CgPairContact c;
        c.xi = wrap(Vec3(U(rng) * L, U(rng) * L, 1e-3 + U(rng) * 8e-3) + shift);
        c.xj = c.xi - Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5) * 1.8e-3;
        c.force = Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5) * 4.0;
        s.pairs.push_back(c);
    }
    for (int i = 0; i < 10; ++i) {
        CgWallContact w;
        w.x = wrap(Vec3(U(rng) * L, U(rng) * L, 0.45e-3) + shift);
        w.point = Vec3(w.x[0], w.x[1], 0.0);
        w.force = Vec3(0.1 * (U(rng) - 0.5), 0.1 * (U(rng) - 0.5), 1.0 + U(rng));
        s.walls.push_back(w);
    }
    return s;
}

std::vector<CoarseGrainer> someGrainers() {
    const Box box{Vec3::Zero(), Vec3::Constant(L)};
    const Box sub{Vec3(1e-3, 2e-3, 0.0), Vec3(8e-3, 7e-3, 9e-3)};
    std::vector<CoarseGrainer> g;
    g.emplace_back(CgGrid(CgCoordinates::XYZ, box, {{12, 10, 14}}), CgKernel(shape("gauss", 0.6e-3), 3));
    g.emplace_back(CgGrid(CgCoordinates::XYZ, sub, {{9, 7, 11}}), CgKernel(shape("lucy", 1.7e-3), 3));
    g.emplace_back(CgGrid(CgCoordinates::XZ, sub, {{12, 1, 14}}), CgKernel(shape("gauss", 0.5e-3), 2));
    g.emplace_back(CgGrid(CgCoordinates::Z, box, {{1, 1, 25}}), CgKernel(shape("heaviside", 1e-3), 1));
    g.emplace_back(CgGrid(CgCoordinates::O, sub, {{1, 1, 1}}), CgKernel(nullptr, 0));
    g.emplace_back(CgGrid::cylindrical(5e-3, 5e-3, 0.0, 4e-3, 0.0, 9e-3, 8, 10), CgKernel(shape("gauss", 0.7e-3), 3));
    return g;
}

}  // namespace

TEST_CASE("CG grid: the snapshot loop equals point evaluation, for any thread count", "[cg][grid]") {
    const CgSnapshot snap = randomSnapshot(11);
    for (const auto& cg : someGrainers()) {
        INFO(cg.grid().describe());
        std::vector<Vec3> pts;
        for (std::size_t p = 0; p < cg.grid().size(); ++p) pts.push_back(cg.grid().point(p));
        CgCounts counts;
        const CgRawFields one = cg.compute(snap, 1, &counts);
        const CgRawFields two = cg.compute(snap, 2);
        const CgRawFields ref = cg.evaluateAt(pts, snap);
        CHECK(counts.particles > 0);
        CHECK(one.data == two.data);  // bitwise: each point sums in the same order
        std::size_t mismatches = 0;
        double big = 0;
        for (double v : ref.data) big = std::max(big, std::abs(v));
        for (std::size_t k = 0; k < ref.data.size(); ++k)
            if (std::abs(one.data[k] - ref.data[k]) > 1e-14 * big) ++mismatches;
        CHECK(mismatches == 0);
    }
}

TEST_CASE("CG grid: fields wrap across periodic directions (a shifted bed gives shifted fields)", "[cg][grid]") {
    const Box box{Vec3::Zero(), Vec3::Constant(L)};
    const int nx = 20, ny = 16, nz = 12, mx = 7, my = 5;
    const CgGrid grid(CgCoordinates::XYZ, box, {{nx, ny, nz}});
    const CoarseGrainer cg(grid, CgKernel(shape("gauss", 0.8e-3), 3));
    const CgRawFields a = cg.compute(randomSnapshot(5), 0);
    const CgRawFields b = cg.compute(randomSnapshot(5, Vec3(mx * L / nx, my * L / ny, 0.0)), 0);
    double big = 0;
    for (double v : a.data) big = std::max(big, std::abs(v));
    double worst = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (int c = 0; c < cgraw::count; ++c)
                    worst = std::max(worst, std::abs(b.at(grid.index((i + mx) % nx, (j + my) % ny, k))[c] -
                                                     a.at(grid.index(i, j, k))[c]));
    CHECK(worst <= 1e-9 * big);  // positions shifted in floating point
}

TEST_CASE("CG grid: a window average counts particles inside and the part of each branch inside", "[cg][grid]") {
    const Box win{Vec3(2e-3, 2e-3, 2e-3), Vec3(5e-3, 6e-3, 7e-3)};
    const double V = 3e-3 * 4e-3 * 5e-3;
    const CoarseGrainer cg(CgGrid(CgCoordinates::O, win, {{1, 1, 1}}), CgKernel(nullptr, 0));
    CgSnapshot s;
    CgParticle in, out;
    in.x = Vec3(3e-3, 3e-3, 3e-3), in.mass = 2e-6, in.radius = 0.5e-3, in.v = Vec3(1, 2, 3);
    out = in;
    out.x[1] = 6.5e-3;
    s.particles = {in, out};
    CgPairContact c;  // 40 % of its branch inside: it crosses x = 5 mm at 40 % of the way
    c.xi = Vec3(4.6e-3, 4e-3, 4e-3);
    c.xj = Vec3(5.6e-3, 4.2e-3, 4.1e-3);
    c.force = Vec3(-3.0, 0.5, 1.0);
    s.pairs = {c};
    const CgRawFields f = cg.compute(s, 1);
    CHECK(f.at(0)[cgraw::density] == Approx(2e-6 / V).epsilon(1e-14));
    CHECK(f.at(0)[cgraw::momentum + 2] == Approx(6e-6 / V).epsilon(1e-14));
    const Vec3 r = c.xi - c.xj;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            CHECK(f.at(0)[cgraw::contactStress + 3 * a + b] == Approx(0.4 * c.force[a] * r[b] / V).epsilon(1e-12));
}

TEST_CASE("CG grid: bad grids are refused naming what is wrong", "[cg][grid]") {
    const Box box{Vec3::Zero(), Vec3::Constant(L)};
    CHECK_THROWS_WITH(CgGrid(CgCoordinates::XYZ, Box{Vec3(0, 0, 1), Vec3(1, 1, 1)}, {{2, 2, 2}}),
                      Catch::Contains("CG window: z from 1 to 1") && Catch::Contains("min < max"));
    CHECK_THROWS_WITH(CgGrid(CgCoordinates::XZ, box, {{4, 1, 0}}), Catch::Contains("0 points along z"));
    CHECK_THROWS_WITH(CgGrid(CgCoordinates::XYZ, box, {{100000, 100000, 10}}), Catch::Contains("more than"));
    CHECK_THROWS_WITH(CgGrid::cylindrical(0, 0, 2e-3, 1e-3, 0, 1, 4, 4), Catch::Contains("0 <= rmin < rmax"));
    CHECK_THROWS_WITH(parseCgCoordinates("XYZZ", "option --coordinates"),
                      Catch::Contains("option --coordinates") && Catch::Contains("RZ") && Catch::Contains("XZ"));
    // a kernel of the wrong dimension is a programming error, not input
    CHECK_THROWS_AS(CoarseGrainer(CgGrid(CgCoordinates::XZ, box, {{4, 1, 4}}), CgKernel(shape("gauss", 1e-3), 3)),
                    Error);
}

TEST_CASE("CG averager: a weighted sum of snapshots, then the fields", "[cg][grid]") {
    const CoarseGrainer cg(CgGrid(CgCoordinates::Z, Box{Vec3::Zero(), Vec3::Constant(L)}, {{1, 1, 16}}),
                           CgKernel(shape("lucy", 2e-3), 1));
    CgSnapshot a = randomSnapshot(3), b = randomSnapshot(4);
    a.hasSpin = true;
    CgAverager avg(cg, 1);
    avg.add(a, 0.25);
    avg.add(b, 0.75);
    CHECK(avg.weight() == 1.0);
    const CgRawFields fa = cg.compute(a, 1), fb = cg.compute(b, 1);
    for (std::size_t k = 0; k < fa.data.size(); ++k)
        CHECK(avg.raw().data[k] == Approx(0.25 * fa.data[k] + 0.75 * fb.data[k]).margin(1e-300).epsilon(1e-14));
    const auto f = avg.fields();
    CHECK_NOTHROW(cgField(f, "spin"));  // a snapshot had omega
    for (std::size_t p = 0; p < cg.grid().size(); ++p)
        CHECK(cgField(f, "density").values[p] == avg.raw().at(p)[cgraw::density]);
}
