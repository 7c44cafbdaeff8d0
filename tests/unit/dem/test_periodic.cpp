// test_periodic.cpp: in a periodic box getParticles() reports positions
// wrapped into the box, also between LIGGGHTS' re-neighbourings.
//
// The sphere moves at 1 m/s from x = 0.0999 m; after 20 steps of 1e-5 s it
// is at 0.0999 + 2e-4 = 0.1001 m, past the periodic face x = 0.1 m, but the
// 0.01 m skin means LIGGGHTS has not re-neighboured (and wrapped) yet. The
// wrapped position is 0.1001 - 0.1 = 1e-4 m (round-off of a few 1e-17 m).
// A non-finite centre is reported as it is, not wrapped: LIGGGHTS'
// Domain::remap would make a NaN along a periodic dimension the box's low
// face, and the exchange's check (which names the particle) would miss it.
#include <catch2/catch.hpp>
#include <mpi.h>

#include <cmath>
#include <limits>
#include <vector>

#include "DemTestSupport.hpp"
#include "LiggghtsDriver.hpp"
#include "atom.h"
#include "lammps.h"

using namespace granair;
using namespace granair::dem;

TEST_CASE("dem: getParticles wraps positions into a periodic box", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("periodic"));
    dem.runFile(test::script("periodic_drift.liggghts"));
    std::vector<ParticleState> p;
    dem.advance(5);  // x = 0.09995: inside, unchanged
    dem.getParticles(p);
    REQUIRE(p.size() == 1);
    CHECK(p[0].x.x() == Approx(0.09995).margin(1e-12));
    dem.advance(15);  // x = 0.1001 unwrapped
    dem.getParticles(p);
    REQUIRE(p.size() == 1);
    CHECK(p[0].x.x() == Approx(1e-4).margin(1e-12));
    CHECK(p[0].x.y() == 0.05);
    CHECK(p[0].x.z() == 0.05);
    CHECK(p[0].v.x() == 1.0);
    // The one-field reads the mapping passes use give the same values
    // (position wrapped likewise).
    const ParticleList& list = dem.particles();
    CHECK(list.position(0).x() == p[0].x.x());
    CHECK(list.position(0).y() == p[0].x.y());
    CHECK(list.id(0) == p[0].id);
    CHECK(list.radius(0) == p[0].radius);
    CHECK(list.velocity(0).x() == 1.0);
    CHECK(list.velocity(0).y() == p[0].v.y());
}

TEST_CASE("dem: a non-finite centre along a periodic dimension is reported, not wrapped", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("periodic_nan"));
    dem.runFile(test::script("periodic_drift.liggghts"));
    dem.advance(5);
    REQUIRE(dem.lammps()->atom->nlocal == 1);
    dem.lammps()->atom->x[0][0] = std::numeric_limits<double>::quiet_NaN();  // x is periodic
    const ParticleList& p = dem.particles();
    REQUIRE(p.size() == 1);
    CHECK(std::isnan(p[0].x.x()));
    CHECK(p[0].x.y() == 0.05);
    dem.lammps()->atom->x[0][0] = std::numeric_limits<double>::infinity();
    CHECK(std::isinf(dem.particles()[0].x.x()));
}
