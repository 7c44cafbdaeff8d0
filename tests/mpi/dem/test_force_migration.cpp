// test_force_migration.cpp: a fluid force set once stays with its particle
// when LIGGGHTS moves the particle to another rank.
//
// crossing.liggghts (zero gravity, box split at x = 0.5 m at 2 ranks): four
// particles start left of 0.5 and get a constant force +m a_i x, four start
// right of it and get -m a_i x, with a_i = (20 + 2 i) m/s2 (distinct, so a
// force ending up on the wrong particle shows). From rest:
//   x_i(t) = x0_i +- a_i t^2 / 2,  v_i(t) = +- a_i t,
// which velocity Verlet reproduces exactly up to round-off (positions ~0.5 m
// after 15000 steps: ~1e-12 m; tolerance 1e-9 m, velocities 1e-9
// relative). By t = 0.15 s every particle has moved 0.225 m or more, so at 2
// ranks all eight have changed rank. Forces are set once at the start, and
// once more by id halfway (after the migration), with the same values.
#include <catch2/catch.hpp>
#include <mpi.h>

#include <map>
#include <vector>

#include "DemTestSupport.hpp"
#include "LiggghtsDriver.hpp"

using namespace granair;
using namespace granair::dem;

namespace {

struct Pushed {
    double x0;  // start [m]
    double a;   // signed acceleration along x [m/s2]
};

// Particles 1..4 (left, pushed +x) and 5..8 (right, pushed -x), as created
// in crossing.liggghts.
std::map<std::int64_t, Pushed> expected() {
    const double x0[] = {0.40, 0.42, 0.44, 0.46, 0.60, 0.58, 0.56, 0.54};
    std::map<std::int64_t, Pushed> e;
    for (int i = 1; i <= 8; ++i) e[i] = {x0[i - 1], (i <= 4 ? 1.0 : -1.0) * (20.0 + 2.0 * i)};
    return e;
}

std::vector<Vec3> forcesFor(const std::vector<ParticleState>& p, const std::vector<double>& m) {
    const auto e = expected();
    std::vector<Vec3> f;
    for (std::size_t k = 0; k < p.size(); ++k) f.emplace_back(m[k] * e.at(p[k].id).a, 0.0, 0.0);
    return f;
}

}  // namespace

TEST_CASE("dem mpi: a fluid force follows its particle across the LIGGGHTS subdomain boundary",
          "[dem][mpi]") {
    int size = 1, rank = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("force_migration_np" + std::to_string(size)));
    dem.runFile(test::script("crossing.liggghts"));
    dem.enableFluidForces();
    REQUIRE(dem.nGlobal() == 8);

    std::vector<ParticleState> p;
    std::vector<double> m;
    dem.getParticles(p);
    dem.getParticleMasses(m);
    // At 2 ranks rank 0 owns x < 0.5: the four left particles.
    std::map<std::int64_t, int> startRank;
    for (const ParticleState& q : p) startRank[q.id] = rank;
    if (size == 2) CHECK(p.size() == 4);
    dem.setFluidForces(forcesFor(p, m));

    const auto e = expected();
    for (int interval = 1; interval <= 5; ++interval) {
        dem.advance(3000);
        const double t = dem.time();
        dem.getParticles(p);
        dem.getParticleMasses(m);
        CHECK(dem.nGlobal() == 8);
        for (const ParticleState& q : p) {
            const Pushed& r = e.at(q.id);
            INFO("rank " << rank << ", particle " << q.id << ", t = " << t << " s");
            CHECK(q.x.x() == Approx(r.x0 + 0.5 * r.a * t * t).margin(1e-9));
            CHECK(q.v.x() == Approx(r.a * t).epsilon(1e-9));
            CHECK(q.v.y() == 0.0);
            CHECK(q.v.z() == 0.0);
        }
        // Halfway, once everything has migrated: set the same forces again
        // through the new local lists (no change in the trajectories).
        if (interval == 3) dem.setFluidForces(forcesFor(p, m));
    }
    if (size == 2) {
        // Every particle now lives on the other rank than at the start.
        int stayed = 0;
        for (const ParticleState& q : p) stayed += startRank.count(q.id);
        CHECK(stayed == 0);
        CHECK(p.size() == 4);
    }
}
