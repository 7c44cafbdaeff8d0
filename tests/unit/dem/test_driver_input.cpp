// test_driver_input.cpp: bad input to the DEM side becomes a granair
// InputError naming the culprit (file, directory, particle, value), raised
// before LIGGGHTS sees it: LIGGGHTS itself would end the process (it
// MPI_Aborts on a missing script). One test case with sections: each opens
// LIGGGHTS in-process, which is cheap, while a test process is not.
#include <catch2/catch.hpp>
#include <mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "DemTestSupport.hpp"
#include "DischargeCounter.hpp"
#include "LiggghtsDriver.hpp"
#include "core/Error.hpp"

using namespace granair;
using namespace granair::dem;
using Catch::Matchers::Contains;

TEST_CASE("dem: bad input is an InputError naming the culprit", "[dem]") {
    SECTION("a missing LIGGGHTS script, named") {
        LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("input_missing_script"));
        const std::string missing = test::script("no_such_script.liggghts");
        CHECK_THAT(test::inputErrorFrom([&] { dem.runFile(missing); }), Contains(missing));
        // The driver is still usable afterwards.
        dem.runFile(test::script("free_fall.liggghts"));
        CHECK(dem.nGlobal() == 1);
    }
    SECTION("a log directory that cannot be created, named") {
        // A directory below a regular file cannot exist.
        std::filesystem::create_directories(GRANAIR_TEST_OUTPUT_DIR);
        const std::string file = test::logDir("input_not_a_directory");
        std::ofstream(file) << "a file, not a directory\n";
        const std::string bad = file + "/logs";
        CHECK_THAT(test::inputErrorFrom([&] { LiggghtsDriver(MPI_COMM_WORLD, bad); }),
                   Contains(bad));
    }
    SECTION("a negative step count") {
        LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("input_advance"));
        dem.runFile(test::script("free_fall.liggghts"));
        CHECK_THAT(test::inputErrorFrom([&] { dem.advance(-1); }), Contains("nSteps = -1"));
    }
    SECTION("fluid forces: not enabled, wrong count, not finite (particle named)") {
        LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("input_forces"));
        dem.runFile(test::script("discharge.liggghts"));
        std::vector<ParticleState> p;
        dem.getParticles(p);
        REQUIRE(p.size() == 5);
        CHECK_THROWS_AS(dem.setFluidForces(std::vector<Vec3>(5, Vec3::Zero())), Error);
        dem.enableFluidForces();
        CHECK_THAT(test::inputErrorFrom(
                       [&] { dem.setFluidForces(std::vector<Vec3>(4, Vec3::Zero())); }),
                   Contains("4 forces given for 5 particles"));
        std::vector<Vec3> f(5, Vec3::Zero());
        f[2].y() = std::nan("");
        CHECK_THAT(test::inputErrorFrom([&] { dem.setFluidForces(f); }),
                   Contains("particle " + std::to_string(p[2].id) + " is"));
    }
    SECTION("discharge planes: sink above the outlet, NaN") {
        LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("input_discharge"));
        dem.runFile(test::script("discharge.liggghts"));
        CHECK_THAT(test::inputErrorFrom([&] { DischargeCounter(dem, 0.05, 0.10); }),
                   Contains("zSink = 0.1"));
        CHECK_THAT(test::inputErrorFrom([&] { DischargeCounter(dem, std::nan(""), 0.0); }),
                   Contains("zOutlet = nan"));
    }
}
