// test_fluid_forces.cpp: fluid forces set through LiggghtsDriver act on the
// right particle, persist until set again, and never leak to new particles.
//
// Reference values: an upward force m g cancels gravity exactly (LIGGGHTS'
// fix gravity adds rmass * (-9.81); we add rmass * 9.81: the sum is exactly
// 0), so a held particle keeps v = 0 and x = x0 to round-off (1e-12 is
// generous). Falling parts follow velocity Verlet, exact for constant
// acceleration (see test_free_fall.cpp; 1e-6 relative).
#include <catch2/catch.hpp>
#include <mpi.h>

#include <cmath>
#include <string>
#include <vector>

#include "DemTestSupport.hpp"
#include "LiggghtsDriver.hpp"
#include "core/Error.hpp"
#include "lammps.h"
#include "modify.h"

using namespace granair;
using namespace granair::dem;

namespace {

// Forces m_i g upward for every particle of the list.
std::vector<Vec3> holdingForces(const std::vector<double>& masses) {
    std::vector<Vec3> f;
    for (double m : masses) f.emplace_back(0.0, 0.0, m * test::gravity);
    return f;
}

// Sets m_i g upward on every particle of the driver, in the order of a fresh
// particle list (what setFluidForces uses).
void holdEveryParticle(LiggghtsDriver& dem) {
    std::vector<ParticleState> p;
    std::vector<double> m;
    dem.getParticles(p);
    dem.getParticleMasses(m);
    dem.setFluidForces(holdingForces(m));
}

}  // namespace

TEST_CASE("dem: an upward fluid force m g holds a sphere still, zero force lets it fall at g",
          "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("hold_and_release"));
    dem.runFile(test::script("free_fall.liggghts"));
    dem.enableFluidForces();

    std::vector<ParticleState> p;
    std::vector<double> m;
    dem.getParticles(p);
    dem.getParticleMasses(m);
    const Vec3 x0 = p[0].x;
    dem.setFluidForces(holdingForces(m));

    // Held for 1000 steps, in two intervals: the force persists across runs.
    dem.advance(400);
    dem.advance(600);
    dem.getParticles(p);
    CHECK(p[0].v.norm() < 1e-12);
    CHECK((p[0].x - x0).norm() < 1e-12);

    // Released: falls from rest at exactly g from the release time.
    dem.setFluidForces({Vec3::Zero()});
    const double t1 = dem.time();
    dem.advance(2000);
    dem.getParticles(p);
    const double t = dem.time() - t1;
    CHECK(t == Approx(2000 * test::dt).epsilon(1e-12));
    CHECK(p[0].v.z() == Approx(-test::gravity * t).epsilon(1e-6));
    CHECK(x0.z() - p[0].x.z() == Approx(0.5 * test::gravity * t * t).epsilon(1e-6));
}

TEST_CASE("dem: particles created after setFluidForces start with zero fluid force", "[dem]") {
    // Particle 1 is held by m g, then deleted; a new particle is created
    // into the same local slot. A per-particle array without set_arrays
    // (LIGGGHTS' fix external, used before) would still hold the old force
    // there; the stored force must be zero, so the new particle falls at g.
    // Then ten more come from fix insert/pack during a run (LIGGGHTS'
    // insertion path): they too.
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("new_particle_force"));
    dem.runFile(test::script("free_fall.liggghts"));
    dem.enableFluidForces();
    holdEveryParticle(dem);
    dem.advance(10);

    dem.command("delete_atoms group all compress no");
    dem.command("create_atoms 1 single 0.03 0.05 0.12 units box");
    dem.command("set group all diameter 0.002 density 2500");
    std::vector<ParticleState> p;
    dem.getParticles(p);
    REQUIRE(p.size() == 1);
    CHECK(p[0].x.z() == 0.12);
    std::vector<double> stored;
    dem.getFluidForces(stored);
    CHECK(stored == std::vector<double>{0.0, 0.0, 0.0});
    const double t0 = dem.time();
    dem.advance(1000);
    dem.getParticles(p);
    const double t = dem.time() - t0;
    CHECK(p[0].v.z() == Approx(-test::gravity * t).epsilon(1e-6));
    CHECK(0.12 - p[0].x.z() == Approx(0.5 * test::gravity * t * t).epsilon(1e-6));

    // Insertion during the next run, at its first step, from rest.
    dem.command("fix pts all particletemplate/sphere 15485863 atom_type 1 "
                "density constant 2500 radius constant 0.001");
    dem.command("fix pdd all particledistribution/discrete 32452843 1 pts 1.0");
    dem.command("region upper block 0.01 0.09 0.01 0.09 0.16 0.19 units box");
    dem.command("fix ins all insert/pack seed 49979693 distributiontemplate pdd "
                "insert_every once overlapcheck yes region upper particles_in_region 10");
    const double t1 = dem.time();
    dem.advance(1000);
    const double fallTime = dem.time() - t1;
    dem.getParticles(p);
    REQUIRE(p.size() == 11);
    for (const ParticleState& q : p) {
        if (q.id == 1) continue;
        INFO("inserted particle " << q.id << " at z = " << q.x.z());
        // Inserted at the first step (or the setup) of the run: the fall
        // lasted between fallTime - dt and fallTime. A fluid force of m g on
        // any of them would leave it near v = 0.
        CHECK(q.v.z() <= -test::gravity * (fallTime - test::dt) * (1 - 1e-9));
        CHECK(q.v.z() >= -test::gravity * fallTime * (1 + 1e-9));
        CHECK(q.v.x() == 0.0);
        CHECK(q.v.y() == 0.0);
    }
}

TEST_CASE("dem: setFluidForces matches particles by tag when LIGGGHTS reordered them", "[dem]") {
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("force_by_tag"));
    dem.runFile(test::script("discharge.liggghts"));
    dem.enableFluidForces();
    std::vector<ParticleState> p;
    std::vector<double> m;
    dem.getParticles(p);
    dem.getParticleMasses(m);
    REQUIRE(p.size() == 5);

    // A new particle (tag 6) changes the local list after getParticles: the
    // five forces must still reach particles 1..5, and particle 6 gets none.
    dem.command("create_atoms 1 single 0.05 0.08 0.10 units box");
    dem.command("set atom 6 diameter 0.002 density 2500");
    dem.setFluidForces(holdingForces(m));
    const double t0 = dem.time();
    dem.advance(500);
    const double t = dem.time() - t0;
    std::vector<ParticleState> after;
    dem.getParticles(after);
    REQUIRE(after.size() == 6);
    for (const ParticleState& q : after) {
        INFO("particle " << q.id);
        if (q.id <= 5) {
            CHECK(q.v.norm() < 1e-12);
        } else {
            CHECK(q.v.z() == Approx(-test::gravity * t).epsilon(1e-6));
        }
    }

    // Deleting particle 3 moves the last local particle into its slot; the
    // list of the last getParticles still names 3: refused, naming it.
    dem.command("group gone id 3");
    dem.command("delete_atoms group gone compress no");
    std::vector<Vec3> f(after.size(), Vec3::Zero());
    CHECK_THAT(test::inputErrorFrom([&] { dem.setFluidForces(f); }),
               Catch::Matchers::Contains("particle 3 "));
}

TEST_CASE("dem: forces one particle at a time act as setFluidForces; problems named at the end", "[dem]") {
    // beginFluidForces / setFluidForce / endFluidForces (what the coupled run
    // uses, with no array of all forces): the held particles stay put as with
    // setFluidForces, getFluidForces reads the stored forces back in the
    // list's order, and a non-finite force or a missing one is an InputError
    // naming it at endFluidForces().
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("force_streamed"));
    dem.runFile(test::script("discharge.liggghts"));
    dem.enableFluidForces();
    std::vector<ParticleState> p;
    std::vector<double> m;
    dem.getParticles(p);
    dem.getParticleMasses(m);
    REQUIRE(p.size() == 5);
    const std::vector<Vec3> f = holdingForces(m);
    dem.beginFluidForces();
    for (std::size_t k = p.size(); k-- > 0;) dem.setFluidForce(k, f[k].data());  // any order
    dem.endFluidForces();
    std::vector<double> stored;
    dem.getFluidForces(stored);
    REQUIRE(stored.size() == 15);
    for (std::size_t k = 0; k < p.size(); ++k)
        for (int a = 0; a < 3; ++a) CHECK(stored[3 * k + a] == f[k][a]);
    dem.advance(500);
    std::vector<ParticleState> after;
    dem.getParticles(after);
    for (const ParticleState& q : after) CHECK(q.v.norm() < 1e-12);

    double bad[3] = {0.0, std::nan(""), 0.0};
    dem.beginFluidForces();
    for (std::size_t k = 0; k < after.size(); ++k) dem.setFluidForce(k, k == 3 ? bad : f[k].data());
    CHECK_THAT(test::inputErrorFrom([&] { dem.endFluidForces(); }),
               Catch::Matchers::Contains("particle " + std::to_string(after[3].id) + " is"));
    dem.beginFluidForces();
    for (std::size_t k = 0; k + 1 < after.size(); ++k) dem.setFluidForce(k, f[k].data());
    CHECK_THAT(test::inputErrorFrom([&] { dem.endFluidForces(); }),
               Catch::Matchers::Contains("4 forces given for 5 particles"));
}

TEST_CASE("dem: a script may define granair's force fixes itself; enableFluidForces uses them", "[dem]") {
    // granair/fluidforce is known to LIGGGHTS from the driver's start (not in
    // the Debian build: registered by granair), so a script can name it.
    LiggghtsDriver dem(MPI_COMM_WORLD, test::logDir("script_force_fixes"));
    dem.runFile(test::script("free_fall.liggghts"));
    dem.command("fix granairFluidForce all property/atom granairFluidForce vector yes no no 0 0 0");
    dem.command("fix granair_fluid all granair/fluidforce granairFluidForce");
    dem.enableFluidForces();
    int applying = 0;
    const LAMMPS_NS::Modify& modify = *dem.lammps()->modify;
    for (int i = 0; i < modify.nfix; ++i)
        if (std::string(modify.fix[i]->style) == "granair/fluidforce") ++applying;
    CHECK(applying == 1);
    holdEveryParticle(dem);
    dem.advance(500);
    std::vector<ParticleState> p;
    dem.getParticles(p);
    for (const ParticleState& q : p) CHECK(q.v.norm() < 1e-12);

    // The same id with another style is refused, naming both styles.
    LiggghtsDriver other(MPI_COMM_WORLD, test::logDir("script_force_fix_style"));
    other.runFile(test::script("free_fall.liggghts"));
    other.command("fix granair_fluid all gravity 9.81 vector 0.0 0.0 1.0");
    CHECK_THROWS_WITH(other.enableFluidForces(), Catch::Matchers::Contains("granair/fluidforce"));
}
