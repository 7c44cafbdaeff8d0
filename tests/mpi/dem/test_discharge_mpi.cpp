// test_discharge_mpi.cpp: the discharge balance at 1 and 2 ranks.
//
// discharge.liggghts split along z at 0.1 m at 2 ranks (processors 1 1 *);
// outlet at 0.12 m, sink at 0.05 m: most particles cross the outlet on rank 1
// and are removed on rank 0, so a discharge flag that did not travel with
// its particle would count it twice. Expected counts at every update come
// from the free-fall closed form (as in tests/unit/dem/test_discharge.cpp;
// the closest approach of a particle to a plane at an update is 6.3e-4 m, so
// they are unambiguous). Counts exact, masses to round-off (1e-12 relative).
#include <catch2/catch.hpp>
#include <mpi.h>

#include <cmath>
#include <vector>

#include "DemTestSupport.hpp"
#include "DischargeCounter.hpp"
#include "LiggghtsDriver.hpp"

using namespace granair;
using namespace granair::dem;

TEST_CASE("dem mpi: discharge accounting closes across ranks", "[dem][mpi]") {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const double zOutlet = 0.12, zSink = 0.05, m = test::sphereMass();
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("discharge_np" + std::to_string(size)));
    dem.runFile(test::script("discharge.liggghts"));
    DischargeCounter counter(dem, zOutlet, zSink);
    std::vector<test::Falling> refs;
    for (double z0 : {0.19, 0.17, 0.15, 0.13, 0.11}) refs.push_back({z0, 0.0});
    counter.update();

    // Until the last particle is removed at t = 0.22 s (LIGGGHTS 3.8 does not
    // run with no particles).
    for (int k = 1; k <= 22; ++k) {
        dem.advance(1000);
        counter.update();
        const double t = dem.time();
        int discharged = 0, removed = 0;
        for (const test::Falling& r : refs) {
            const double z = r.z(t);
            REQUIRE(std::abs(z - zOutlet) > 1e-9);
            REQUIRE(std::abs(z - zSink) > 1e-9);
            discharged += z < zOutlet;
            removed += z <= zSink;
        }
        const int inserted = static_cast<int>(refs.size());
        const DischargeBalance& b = counter.balance();
        INFO("update " << k << " at t = " << t << " s, " << size << " rank(s)");
        CHECK(b.inserted == inserted);
        CHECK(b.discharged == discharged);
        CHECK(b.removed == removed);
        CHECK(b.present == inserted - removed);
        CHECK(b.lost == 0);
        CHECK(b.dischargedMass == Approx(discharged * m).epsilon(1e-12));
        CHECK(b.removedMass == Approx(removed * m).epsilon(1e-12));
        CHECK(dem.nGlobal() == inserted - removed);
        if (k == 5) {
            // Inserted at z = 0.19 m: on rank 1 at 2 ranks.
            dem.command("create_atoms 1 single 0.05 0.02 0.19 units box");
            dem.command("set atom 6 diameter 0.002 density 2500");
            refs.push_back({0.19, t});
        }
    }
    const DischargeBalance& b = counter.balance();
    CHECK(b.inserted == 6);
    CHECK(b.discharged == 6);
    CHECK(b.removed == 6);
    CHECK(b.present == 0);
    CHECK(b.lost == 0);
    CHECK(std::abs(b.lostMass) <= 1e-12 * b.insertedMass);
}
