// LiggghtsDriver.hpp: one LIGGGHTS 3.8 instance driven as a library.
//
// The DEM input stays an ordinary LIGGGHTS script (box, walls, pair style,
// insertion, integrator, gravity, timestep) without the `run` of the coupled
// part; the driver runs the steps, reads the particles and applies the fluid
// forces. Calls marked "collective" must be made by every rank of the
// communicator in the same order (they run LIGGGHTS commands or reductions).
//
// Errors: granair's own checks throw granair::InputError / granair::Error
// on all ranks together. An error *inside* LIGGGHTS cannot be caught (3.8
// has no exceptions: it ends the job itself, see README.md); the driver
// makes sure its ERROR line appears on stderr as "LIGGGHTS error: ...".
#pragma once
#include <mpi.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/Particle.hpp"
#include "core/ParticleList.hpp"
#include "core/Vec3.hpp"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace granair::dem {

class FluidForceStore;

class LiggghtsDriver {
public:
    // Opens LIGGGHTS on comm with its log in <logDir>/log.liggghts and its
    // screen in <logDir>/screen.liggghts (logDir is created if missing).
    // InputError naming the path if the directory or files cannot be
    // written. Requires MPI to be initialised. Collective.
    LiggghtsDriver(MPI_Comm comm, const std::string& logDir);
    // Closes LIGGGHTS (lammps_close); never finalises MPI. Collective.
    ~LiggghtsDriver();
    LiggghtsDriver(const LiggghtsDriver&) = delete;
    LiggghtsDriver& operator=(const LiggghtsDriver&) = delete;

    // Runs a LIGGGHTS input script. InputError naming the file if rank 0
    // cannot read it (checked before LIGGGHTS sees it: LIGGGHTS would
    // MPI_Abort). Collective.
    void runFile(const std::string& path);
    // Runs one LIGGGHTS command. Collective.
    void command(const std::string& line);

    double timestep() const;  // [s]
    std::int64_t step() const;
    double time() const;  // simulated time [s]
    // After a read_restart LIGGGHTS 3.8 does not carry on its simulated time
    // (the step number it keeps): from now on time() is t [s] plus the steps
    // since, times the timestep.
    void alignTime(double t);
    std::int64_t nGlobal() const;  // particles on all ranks. Collective.
    int nLocal() const;  // particles owned by this rank

    // Creates the fluid-force fixes (see FluidForceStore.hpp); every
    // particle starts with zero fluid force. Collective.
    void enableFluidForces();
    // Fluid force [N] of each local particle, in the order of the last
    // getParticles() call on this rank; kept until set again (constant over
    // the DEM steps of a coupling interval). Particles created since then
    // keep their force (zero when new). If LIGGGHTS reordered its atoms since
    // (a command deleted or created some), forces are matched by tag. The new
    // force acts from the first half-step of the next advance() (see .cpp;
    // assumes no fix overrides f after fix external, e.g. freeze/setforce).
    // InputError if the size is wrong, a force is not finite, or a particle
    // of that list is no longer on this rank. Collective (the check).
    void setFluidForces(const std::vector<Vec3>& forces);
    // The same with the forces as n x 3 contiguous doubles (x y z per particle).
    void setFluidForces(const double* xyz, std::size_t n);

    // The same one particle at a time, with no array of all forces in
    // between (the coupled run writes each force as the exchange brings it):
    // beginFluidForces() finds the particles of the last getParticles() (by
    // tag if LIGGGHTS reordered them), setFluidForce(k, f) gives particle k of
    // that list the force f[0..2] exactly as setFluidForces does,
    // endFluidForces() raises the first problem as InputError on all ranks
    // together (collective, the only reduction): a particle of the list is
    // gone (then no force is stored), a force was not finite (it is not
    // stored, the others are), or not every particle of the list was given
    // (counted).
    void beginFluidForces();
    void setFluidForce(std::size_t k, const double* f);
    void endFluidForces();
    // The stored fluid force of each particle of the last getParticles() (3
    // doubles each, in that order), for output; InputError as
    // beginFluidForces() if one is gone. Collective.
    void getFluidForces(std::vector<double>& xyz);

    // Advances the DEM by nSteps steps: a full LIGGGHTS setup (`run N`) the
    // first time and after any command(), `run N pre no post no` otherwise.
    // Collective.
    void advance(int nSteps);

    // Local particles (id = LIGGGHTS tag, x, v, radius) in LIGGGHTS' local
    // order; remembered for setFluidForces. In a periodic box x is wrapped
    // into the box (LIGGGHTS itself wraps only when it re-neighbours).
    void getParticles(std::vector<ParticleState>& out);
    // The same particles as a view of LIGGGHTS' own arrays, read when used
    // (no copy: the coupled run's list), remembered for setFluidForces as
    // getParticles does. Valid until the next advance() or command().
    const ParticleList& particles();
    // Mass [kg] of each local particle, same order as getParticles (valid
    // until the next command or advance).
    void getParticleMasses(std::vector<double>& out) const;

    // LIGGGHTS' processor grid (procs along x, y, z), once the box exists.
    std::array<int, 3> processorGrid() const;
    // Particles on each rank (index = rank). Collective.
    std::vector<std::int64_t> particlesPerRank() const;

    // What LIGGGHTS' neighbour binning will allocate on the busiest rank:
    // bins of binSize (neigh_modify binsize, or half the neighbour cutoff
    // 2 r_max + skin) over this rank's subdomain plus the ghost shell.
    struct NeighbourBins {
        double cutoff = 0;    // 2 r_max + skin [m]
        double binSize = 0;   // [m]
        bool userBinSize = false;
        double bins = 0;      // on the rank with the most
        int rank = 0;         // that rank
        std::int64_t particlesThere = 0;
    };
    // Collective.
    NeighbourBins neighbourBins() const;

    MPI_Comm comm() const { return comm_; }
    int rank() const { return rank_; }
    const std::string& logDir() const { return logDir_; }
    std::string logPath() const { return logDir_ + "/log.liggghts"; }
    // For dem-side classes that need LIGGGHTS internals (DischargeCounter).
    LAMMPS_NS::LAMMPS* lammps() { return lmp_; }

private:
    // particles(): particle i of LIGGGHTS' local arrays, its position wrapped
    // into a periodic box as getParticles() reports it.
    class LocalParticles final : public ParticleList {
    public:
        std::size_t size() const override { return n_; }
        ParticleState operator[](std::size_t i) const override;
        Vec3 position(std::size_t i) const override;
        std::int64_t id(std::size_t i) const override;
        double radius(std::size_t i) const override;
        Vec3 velocity(std::size_t i) const override;

    private:
        friend class LiggghtsDriver;
        LAMMPS_NS::LAMMPS* lmp_ = nullptr;
        std::size_t n_ = 0;
        bool periodic_ = false;
        // An orthogonal box's periodic extent (lo = -inf, hi = inf along a
        // dimension that is not periodic): a centre inside needs no remap.
        bool triclinic_ = false;
        double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
    };
    LocalParticles local_;

    void checkLogDir() const;
    // Stores force f of local particle i and patches atom->f by its change.
    void storeForce(int i, const double* f);

    MPI_Comm comm_ = MPI_COMM_NULL;  // our duplicate of the caller's comm
    int rank_ = 0;
    std::string logDir_;
    LAMMPS_NS::LAMMPS* lmp_ = nullptr;
    std::FILE* screen_ = nullptr;  // the echoing screen stream we installed
    std::unique_ptr<FluidForceStore> forces_;
    bool needsSetup_ = true;  // a command ran since the last full setup
    bool aligned_ = false;    // alignTime() was called
    double alignedTime_ = 0;  // time [s] at step alignedStep_
    std::int64_t alignedStep_ = 0;
    std::vector<int> lastTags_;  // tags in the order of the last getParticles
    // LIGGGHTS' local index of each particle of lastTags_ (empty: the same
    // order, no reordering since getParticles), from findLastParticles().
    std::vector<int> lastIndex_;
    // Between beginFluidForces() and endFluidForces(): forces set, first problem.
    std::size_t forcesSet_ = 0;
    std::string forceProblem_;
    // Fills lastIndex_ (or clears it: same order); the problem, if any.
    std::string findLastParticles();
    int localIndex(std::size_t k) const { return lastIndex_.empty() ? static_cast<int>(k) : lastIndex_[k]; }
};

}  // namespace granair::dem
