// test_discharge.cpp: DischargeCounter against free-fall closed forms.
//
// discharge.liggghts: five spheres at rest at z0 = 0.19, 0.17, 0.15, 0.13,
// 0.11 m, never touching; a sixth is created at rest at z0 = 0.19 m at
// t = 0.05 s. Each follows z(t) = z0 - g (t - t0)^2 / 2 (velocity Verlet is
// exact for it, see test_free_fall.cpp). With the outlet at 0.10 m and the
// sink at 0.05 m and an update every 1000 steps (0.01 s), the expected
// counts at every update follow from the closed form; the test first checks
// that no particle is within 1e-9 m of either plane at an update (the
// smallest distance is 6.3e-4 m), so the expected counts are unambiguous.
// Counts must match exactly; masses are sums of m = rho 4/3 pi r^3 and
// match to round-off (relative 1e-12).
#include <catch2/catch.hpp>
#include <mpi.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "DemTestSupport.hpp"
#include "DischargeCounter.hpp"
#include "LiggghtsDriver.hpp"
#include "core/Error.hpp"

using namespace granair;
using namespace granair::dem;

namespace {

constexpr double zOutlet = 0.10, zSink = 0.05;

}  // namespace

TEST_CASE("dem: discharge counts each particle once, removes it at the sink, balance closes",
          "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("discharge"));
    dem.runFile(test::script("discharge.liggghts"));
    DischargeCounter counter(dem, zOutlet, zSink);
    std::vector<test::Falling> refs;
    for (double z0 : {0.19, 0.17, 0.15, 0.13, 0.11}) refs.push_back({z0, 0.0});

    const double m = test::sphereMass();
    counter.update();
    CHECK(counter.balance().inserted == 5);
    CHECK(counter.balance().insertedMass == Approx(5 * m).epsilon(1e-12));

    // Until the last particle is removed (t = 0.22 s): LIGGGHTS 3.8 refuses to
    // run with no particle left ("Atom types must start from 1").
    for (int k = 1; k <= 22; ++k) {
        dem.advance(1000);
        counter.update();
        const double t = dem.time();
        REQUIRE(t == Approx(k * 0.01).epsilon(1e-12));
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
        INFO("update " << k << " at t = " << t << " s");
        CHECK(b.inserted == inserted);
        CHECK(b.discharged == discharged);
        CHECK(b.removed == removed);
        CHECK(b.present == inserted - removed);
        CHECK(b.lost == 0);
        CHECK(dem.nGlobal() == inserted - removed);
        CHECK(b.dischargedMass == Approx(discharged * m).epsilon(1e-12));
        CHECK(b.removedMass == Approx(removed * m).epsilon(1e-12));
        CHECK(b.presentMass == Approx((inserted - removed) * m).epsilon(1e-12).margin(1e-20));
        // The particles still present are where the closed form says.
        std::vector<ParticleState> p;
        dem.getParticles(p);
        for (const ParticleState& q : p) {
            const test::Falling& r = refs.at(q.id <= 5 ? q.id - 1 : 5);
            CHECK(q.x.z() == Approx(r.z(t)).epsilon(1e-9));
            CHECK(q.x.z() > zSink);
        }

        if (k == 5) {
            // A particle inserted during the discharge (tag 6: LIGGGHTS gives
            // max present tag + 1, and none has been removed yet).
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
    CHECK(b.reusedTags == 0);
    CHECK(std::abs(b.lostMass) <= 1e-12 * b.insertedMass);

    std::ostringstream report;
    counter.report(report);
    CHECK_THAT(report.str(), Catch::Matchers::Contains("inserted"));
    CHECK_THAT(report.str(), !Catch::Matchers::Contains("LOST"));
}

TEST_CASE("dem: a particle that leaves the box is reported as lost, not removed", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("discharge_lost"));
    dem.runFile(test::script("discharge.liggghts"));
    DischargeCounter counter(dem, zOutlet, zSink);
    counter.update();
    // Particle 5 (x = 0.09 m) at 2 m/s towards the x = 0.1 m wall: it leaves
    // the box after 5 ms, before reaching the outlet (z0 = 0.11 m).
    dem.command("group runaway id 5");
    dem.command("velocity runaway set 2.0 0 0 units box");
    dem.advance(1000);
    counter.update();
    const DischargeBalance& b = counter.balance();
    CHECK(b.inserted == 5);
    CHECK(b.present == 4);
    CHECK(b.removed == 0);
    CHECK(b.lost == 1);
    CHECK(b.lostMass == Approx(test::sphereMass()).epsilon(1e-9));
    CHECK(b.discharged == 0);
    std::ostringstream report;
    counter.report(report);
    CHECK_THAT(report.str(), Catch::Matchers::Contains("LOST PARTICLES: 1"));
}

TEST_CASE("dem: a deleted highest tag is reused by LIGGGHTS and counted as such", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("discharge_tags"));
    dem.runFile(test::script("discharge.liggghts"));
    DischargeCounter counter(dem, zOutlet, zSink);
    counter.update();
    dem.command("group last id 5");
    dem.command("delete_atoms group last compress no");
    dem.command("create_atoms 1 single 0.09 0.05 0.11 units box");
    dem.command("set atom 5 diameter 0.002 density 2500");
    counter.update();
    // The new particle is counted as inserted although its tag is old.
    const DischargeBalance& b = counter.balance();
    CHECK(b.inserted == 6);
    CHECK(b.reusedTags == 1);
    CHECK(b.present == 5);
    CHECK(b.lost == 1);  // the deleted particle 5 never reached the sink
}
