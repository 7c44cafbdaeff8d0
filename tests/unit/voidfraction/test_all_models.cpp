// Properties every registered void-fraction model must have: the stencil
// contract and exact conservation of solid volume, on meshes whose cells are
// much smaller and much larger than the particles, at faces, edges, corners
// and domain boundaries, and on a decomposed mesh. Each model runs with the
// parameters in tests/data/voidfraction/<type>.dict, so a newly registered
// model is covered (and fails here until it has a data file).
#include <catch2/catch.hpp>
#include <numeric>

#include "ModelTestSupport.hpp"
#include "VoidFractionTestSupport.hpp"
#include "mapping/BoxMesh.hpp"
#include "voidfraction/SolidVolume.hpp"

using granair::BoxMesh;
using granair::CellWeight;
using granair::ParticleState;
using granair::Vec3;

namespace {

// Conservation tolerance, relative to the total particle volume: every
// stencil sums to 1 within ~1e-15 and the totals add ~10^3 terms, so 1e-12
// leaves a wide margin for round-off and none for a lost or doubled point.
constexpr double conservationTol = 1e-12;

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// Locate, check every stencil, accumulate, and compare totals.
void checkConservation(const BoxMesh& mesh, const granair::VoidFractionModel& model,
                       const std::vector<ParticleState>& particles) {
    std::vector<int> cells;
    double total = 0;
    std::vector<CellWeight> st;
    for (const auto& p : particles) {
        const int c = mesh.findCell(p.x);
        INFO("particle " << p.id << " at " << p.x.transpose() << " r " << p.radius);
        REQUIRE(c >= 0);
        cells.push_back(c);
        total += granair::sphereVolume(p.radius);
        model.stencil(mesh, p, c, st);
        vftest::checkStencil(mesh, st);
    }
    std::vector<double> solid;
    granair::accumulateSolidVolume(mesh, model, particles, cells, solid);
    REQUIRE(solid.size() == static_cast<std::size_t>(mesh.nCells()));
    for (double s : solid) REQUIRE(s >= 0);
    CHECK(sum(solid) == Approx(total).epsilon(conservationTol));
}

std::vector<ParticleState> randomParticles(vftest::Random& rnd, int n, const Vec3& lo, const Vec3& hi,
                                           double rMin, double rMax) {
    std::vector<ParticleState> ps(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        ps[i].id = i + 1;
        for (int a = 0; a < 3; ++a) ps[i].x[a] = rnd.uniform(lo[a], hi[a]);
        ps[i].radius = rnd.uniform(rMin, rMax);
    }
    return ps;
}

}  // namespace

// Sections of one test case: each ctest test pays ~0.5 s of MPI start-up.
TEST_CASE("every registered void-fraction model: stencil contract and exact conservation", "[voidfraction]") {
    SECTION("every registered model has its parameter file, and the registry lists the names on error") {
        const auto& reg = granair::voidFractionModels();
        modeltest::checkReferenceData(reg, "voidfraction", vftest::dataDir(), ".dict", false);
        for (const auto& name : reg.names()) CHECK(vftest::modelFromData(name)->name() == name);
        const auto bad = granair::Dictionary::fromString("type smooth;", "couplingProperties");
        CHECK_THROWS_AS(reg.create(bad), granair::InputError);
        CHECK_THROWS_WITH(reg.create(bad),
                          Catch::Matchers::Contains("couplingProperties") &&
                              Catch::Matchers::Contains("unknown void-fraction model 'smooth'") &&
                              Catch::Matchers::Contains("Known void-fraction model names:" +
                                                        modeltest::knownNames(reg)));
    }

    SECTION("every model conserves solid volume for random particles on fine, coarse and stretched cells") {
        const Vec3 lo(0, 0, 0), hi(1, 1, 1);
        // Cells of 0.02 m (particles up to 8 cells wide), 0.25 m (cells up to
        // 30 radii wide) and stretched 0.0125 x 0.1 x 0.33 m (both at once).
        const std::vector<BoxMesh::Index3> grids{{50, 50, 50}, {4, 4, 4}, {80, 10, 3}};
        for (const auto& name : granair::voidFractionModels().names()) {
            const auto model = vftest::modelFromData(name);
            for (const auto& n : grids) {
                INFO("model " << name << ", mesh " << n[0] << "x" << n[1] << "x" << n[2]);
                const BoxMesh mesh(lo, hi, n);
                vftest::Random rnd(20240611);
                // Centres anywhere in the box (particles may stick out of it).
                checkConservation(mesh, *model, randomParticles(rnd, 400, lo, hi, 0.002, 0.08));
            }
        }
    }

    SECTION("every model conserves volume for particles on faces, edges, corners and the domain boundary") {
        const Vec3 lo(0, 0, 0), hi(1, 1, 1);
        // Interior faces at multiples of 0.25 (coarse) and 0.05 (fine).
        const std::vector<Vec3> spots{
            {0.25, 0.4, 0.6}, {0.25, 0.5, 0.6}, {0.25, 0.5, 0.75}, {0.5, 0.5, 0.5},   // face, edge, corners
            {0.0, 0.4, 0.6},  {1.0, 0.4, 0.6},  {0.3, 0.0, 0.6},   {0.3, 1.0, 0.6},   // x/y == lo, hi
            {0.3, 0.4, 0.0},  {0.3, 0.4, 1.0},  {1.0, 1.0, 0.3},   {0.0, 0.0, 0.5},   // z, domain edges
            {0.0, 0.0, 0.0},  {1.0, 1.0, 1.0},  {0.0, 1.0, 0.0},   {1.0, 0.0, 1.0}};  // domain corners
        for (const auto& name : granair::voidFractionModels().names()) {
            const auto model = vftest::modelFromData(name);
            for (const BoxMesh::Index3& n : {BoxMesh::Index3{4, 4, 4}, BoxMesh::Index3{20, 20, 20}}) {
                const BoxMesh mesh(lo, hi, n);
                std::vector<ParticleState> ps;
                for (double r : {0.02, 0.1, 0.3})  // smaller than, about, and larger than a coarse cell
                    for (const Vec3& x : spots) {
                        ParticleState p;
                        p.id = static_cast<std::int64_t>(ps.size()) + 1;
                        p.x = x;
                        p.radius = r;
                        ps.push_back(p);
                    }
                INFO("model " << name << ", mesh " << n[0] << "^3");
                checkConservation(mesh, *model, ps);
            }
        }
    }

    SECTION("every model conserves volume on one block of a decomposed mesh") {
        const Vec3 lo(0, 0, 0), hi(1, 1, 1);
        const BoxMesh::Index3 n{24, 24, 24};
        // An interior block: every particle near its faces has satellites / kernel
        // cells on other (absent) ranks.
        const BoxMesh block(lo, hi, n, {6, 0, 8}, {18, 24, 14});
        const granair::Box b = block.bounds();
        for (const auto& name : granair::voidFractionModels().names()) {
            INFO("model " << name);
            const auto model = vftest::modelFromData(name);
            vftest::Random rnd(77);
            checkConservation(block, *model, randomParticles(rnd, 300, b.lo, b.hi, 0.005, 0.06));
            // And the slabs of a 3-way split along y.
            for (int part = 0; part < 3; ++part) {
                const BoxMesh slab = BoxMesh::slab(lo, hi, n, 3, part, 1);
                const granair::Box sb = slab.bounds();
                checkConservation(slab, *model, randomParticles(rnd, 100, sb.lo, sb.hi, 0.005, 0.06));
            }
        }
    }

    SECTION("a particle larger than a cell: every model conserves it; centre keeps it in one cell, divided and "
            "gaussian spread it") {
        // 0.025 m cells (V_c = 1.56e-5 m3), particle radius 0.05 m (V_p = 5.24e-4 m3 = 33.5 V_c).
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {40, 40, 40});
        const double vc = mesh.cellVolume(0);
        vftest::Random rnd(5);
        const auto ps = randomParticles(rnd, 10, Vec3::Constant(0.2), Vec3::Constant(0.8), 0.05, 0.05);
        const double vp = granair::sphereVolume(0.05);
        for (const auto& name : granair::voidFractionModels().names()) {
            const auto model = vftest::modelFromData(name);
            for (const auto& p : ps) {
                INFO("model " << name << ", particle at " << p.x.transpose());
                std::vector<double> solid;
                granair::accumulateSolidVolume(mesh, *model, {p}, {mesh.findCell(p.x)}, solid);
                int filled = 0;
                double largest = 0;
                for (double s : solid) {
                    filled += s > 0;
                    largest = std::max(largest, s);
                }
                CHECK(sum(solid) == Approx(vp).epsilon(conservationTol));
                if (name == "centre") {
                    // Raw, unfloored: one cell holds 33.5 times its own volume.
                    CHECK(filled == 1);
                    CHECK(largest == Approx(vp).epsilon(1e-15));
                    CHECK(largest > vc);
                } else if (name == "divided" || name == "gaussian") {
                    CHECK(filled > 1);
                    CHECK(largest < 0.5 * vp);
                }
            }
        }
    }
}
