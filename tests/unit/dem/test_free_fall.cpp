// test_free_fall.cpp: a single sphere released from rest under gravity alone.
//
// Reference: constant acceleration, v = -g t, z = z0 - g t^2 / 2. LIGGGHTS'
// nve/sphere is velocity Verlet, which integrates a constant force exactly:
// v_n = -g n dt and x_n = x0 - g dt^2 n^2 / 2 in exact arithmetic, so the
// only error is round-off (~1e-15 relative per step). The tolerance 1e-6
// relative (of the velocity and of the drop z0 - z) is far above that and far
// below any physical error (a wrong g, a missing or doubled half-kick, a lost
// step would all show at the 1e-4 level or worse).
#include <catch2/catch.hpp>
#include <mpi.h>

#include <vector>

#include "DemTestSupport.hpp"
#include "LiggghtsDriver.hpp"

using namespace granair;
using namespace granair::dem;

TEST_CASE("dem: a sphere falling from rest follows v = g t and z = z0 - g t^2/2", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("free_fall"));
    dem.runFile(test::script("free_fall.liggghts"));
    const double z0 = 0.15, g = test::gravity;

    std::vector<ParticleState> p;
    dem.getParticles(p);
    REQUIRE(p.size() == 1);
    REQUIRE(p[0].x.z() == z0);
    REQUIRE(p[0].v.norm() == 0.0);
    std::vector<double> m;
    dem.getParticleMasses(m);
    // rmass from `set density`: rho 4/3 pi r^3 (round-off only).
    CHECK(m[0] == Approx(test::sphereMass()).epsilon(1e-12));
    CHECK(p[0].radius == Approx(test::sphereRadius).epsilon(1e-12));

    // Several intervals: the first run does LIGGGHTS' setup, the later ones
    // continue with `pre no`; the closed form must hold across all of them.
    long steps = 0;
    for (int n : {1, 9, 990, 2000, 5000}) {
        dem.advance(n);
        steps += n;
        const double t = steps * test::dt;
        dem.getParticles(p);
        REQUIRE(p.size() == 1);
        INFO("after " << steps << " steps, t = " << t << " s");
        CHECK(p[0].v.z() == Approx(-g * t).epsilon(1e-6));
        CHECK(z0 - p[0].x.z() == Approx(0.5 * g * t * t).epsilon(1e-6));
        // No force acts sideways.
        CHECK(p[0].v.x() == 0.0);
        CHECK(p[0].v.y() == 0.0);
    }
}
