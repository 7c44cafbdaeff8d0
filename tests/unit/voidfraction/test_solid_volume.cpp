// accumulateSolidVolume: sums weight * V_p per cell; bad input names the particle.
#include <catch2/catch.hpp>
#include <cmath>

#include "VoidFractionTestSupport.hpp"
#include "mapping/BoxMesh.hpp"
#include "voidfraction/CentreVoidFraction.hpp"
#include "voidfraction/SolidVolume.hpp"

using granair::BoxMesh;
using granair::ParticleState;
using granair::Vec3;

namespace {
ParticleState particle(std::int64_t id, const Vec3& x, double r) {
    ParticleState p;
    p.id = id;
    p.x = x;
    p.radius = r;
    return p;
}
}  // namespace

// Sections of one test case: each ctest test pays ~0.5 s of MPI start-up.
TEST_CASE("accumulateSolidVolume sums weight times particle volume per cell", "[voidfraction]") {
    SECTION("centre model puts 4/3 pi r^3 in each particle's cell and adds up") {
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {2, 2, 2});
        const granair::CentreVoidFraction centre;
        const std::vector<ParticleState> ps{particle(1, Vec3(0.1, 0.1, 0.1), 0.1),
                                            particle(2, Vec3(0.2, 0.3, 0.1), 0.05),
                                            particle(3, Vec3(0.9, 0.9, 0.9), 0.2)};
        std::vector<int> cells;
        for (const auto& p : ps) cells.push_back(mesh.findCell(p.x));
        std::vector<double> solid;
        granair::accumulateSolidVolume(mesh, centre, ps, cells, solid);
        REQUIRE(solid.size() == 8);
        // Closed form: V = 4/3 pi r^3.
        CHECK(solid[0] == Approx(4.0 / 3 * M_PI * (1e-3 + 1.25e-4)).epsilon(1e-15));
        CHECK(solid[7] == Approx(4.0 / 3 * M_PI * 8e-3).epsilon(1e-15));
        // A second call adds to what is there.
        granair::accumulateSolidVolume(mesh, centre, ps, cells, solid);
        CHECK(solid[7] == Approx(2 * 4.0 / 3 * M_PI * 8e-3).epsilon(1e-15));
    }

    SECTION("a particle not on this rank, a bad radius or mismatched arrays are errors") {
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {2, 2, 2});
        const granair::CentreVoidFraction centre;
        std::vector<double> solid;
        const std::vector<ParticleState> one{particle(4711, Vec3(1.5, 0.5, 0.5), 0.1)};
        CHECK_THROWS_AS(granair::accumulateSolidVolume(mesh, centre, one, {-1}, solid), granair::InputError);
        CHECK_THROWS_WITH(granair::accumulateSolidVolume(mesh, centre, one, {-1}, solid),
                          Catch::Matchers::Contains("particle 4711") && Catch::Matchers::Contains("1.5"));
        CHECK_THROWS_AS(granair::accumulateSolidVolume(mesh, centre, one, {8}, solid), granair::InputError);
        for (double r : {-0.1, std::nan("")}) {
            const std::vector<ParticleState> badR{particle(12, Vec3(0.5, 0.5, 0.5), r)};
            CHECK_THROWS_WITH(
                granair::accumulateSolidVolume(mesh, centre, badR, {7}, solid),
                Catch::Matchers::Contains("particle 12") && Catch::Matchers::Contains("radius"));
        }
        CHECK_THROWS_AS(granair::accumulateSolidVolume(mesh, centre, one, {0, 1}, solid), granair::Error);
        std::vector<double> wrongSize(3, 0.0);
        CHECK_THROWS_AS(granair::accumulateSolidVolume(mesh, centre, one, {0}, wrongSize), granair::Error);
    }
}
