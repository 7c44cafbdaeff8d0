// test_advance.cpp: advance(N) moves LIGGGHTS by exactly N steps and N dt.
//
// Steps are integers: exact. Time: LIGGGHTS returns atime + (step -
// atimestep) dt, so the increment equals N dt to round-off of one sum
// (relative 1e-12 is generous).
#include <catch2/catch.hpp>
#include <mpi.h>

#include "DemTestSupport.hpp"
#include "LiggghtsDriver.hpp"

using namespace granair;
using namespace granair::dem;

TEST_CASE("dem: advance(N) advances exactly N steps and N dt", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("advance"));
    dem.runFile(test::script("free_fall.liggghts"));
    REQUIRE(dem.step() == 0);
    REQUIRE(dem.time() == 0.0);
    REQUIRE(dem.timestep() == test::dt);
    REQUIRE(dem.nGlobal() == 1);
    REQUIRE(dem.nLocal() == 1);

    // First run (full setup), then `pre no` continuations.
    std::int64_t step = 0;
    double time = 0;
    for (int n : {7, 13, 1, 100}) {
        dem.advance(n);
        step += n;
        time += n * test::dt;
        CHECK(dem.step() == step);
        CHECK(dem.time() == Approx(time).epsilon(1e-12));
    }
    // A command in between forces a full setup again; a new timestep is used
    // from there on and the time keeps accumulating.
    dem.command("timestep 2e-5");
    CHECK(dem.timestep() == 2e-5);
    dem.advance(10);
    CHECK(dem.step() == step + 10);
    CHECK(dem.time() == Approx(time + 10 * 2e-5).epsilon(1e-12));
    // Zero steps: nothing moves.
    dem.advance(0);
    CHECK(dem.step() == step + 10);
}
