// LiggghtsDriver.cpp: see LiggghtsDriver.hpp.
#include "LiggghtsDriver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <system_error>
#include <unordered_map>

#include "FluidForceFix.hpp"
#include "FluidForceStore.hpp"
#include "ScreenErrorEcho.hpp"
#include "atom.h"
#include "comm.h"
#include "core/CapacityBytes.hpp"
#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "domain.h"
#include "lammps.h"
#include "library.h"
#include "neighbor.h"
#include "universe.h"
#include "update.h"

namespace granair::dem {

namespace fs = std::filesystem;

namespace {

// granair reads per-particle radius and mass: the granular (sphere) style.
void requireSpheres(const LAMMPS_NS::Atom& atom) {
    if (!atom.radius || !atom.rmass)
        fail<InputError>("LIGGGHTS atom style has no per-particle radius and mass: the DEM "
                         "script must use `atom_style granular` (or sphere)");
}

// Neighbor's user bin size is protected; a pointer to member taken through
// a derived class reads it without touching anything else.
struct NeighborInternals : LAMMPS_NS::Neighbor {
    static bool userBinSize(const LAMMPS_NS::Neighbor& n) { return n.*(&NeighborInternals::binsizeflag) != 0; }
    static double binSize(const LAMMPS_NS::Neighbor& n) { return n.*(&NeighborInternals::binsize_user); }
};

// Can this process create/overwrite `path` the way LIGGGHTS' fopen(path,"w")
// will? ("a" does not truncate an existing file.)
bool writable(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "a");
    if (!f) return false;
    std::fclose(f);
    return true;
}

// The two problems a list of fluid forces can have, worded once for
// setFluidForces (the whole array) and setFluidForce/endFluidForces (one at a time).
std::string forceCountProblem(std::size_t given, std::size_t particles) {
    std::ostringstream problem;
    problem << "setFluidForces: " << given << " forces given for " << particles
            << " particles of the last getParticles() call on this rank";
    return problem.str();
}

std::string nonFiniteForceProblem(int tag, const double* f) {
    std::ostringstream problem;
    problem.precision(10);
    problem << "setFluidForces: fluid force on particle " << tag << " is (" << f[0] << ' ' << f[1] << ' ' << f[2]
            << ") N, expected finite values";
    return problem.str();
}

bool allFinite3(const double* f) { return std::isfinite(f[0]) && std::isfinite(f[1]) && std::isfinite(f[2]); }

}  // namespace

void LiggghtsDriver::checkLogDir() const {
    // Only rank 0 opens LIGGGHTS' files; the others wait for its verdict.
    std::string problem;
    if (rank_ == 0) {
        std::error_code ec;
        fs::create_directories(logDir_, ec);
        if (!fs::is_directory(logDir_))
            problem = "LIGGGHTS log directory '" + logDir_ + "' cannot be created" +
                      (ec ? " (" + ec.message() + ")" : std::string(" (not a directory)"));
        else
            for (const char* name : {"/log.liggghts", "/screen.liggghts"})
                if (problem.empty() && !writable(logDir_ + name))
                    problem = "LIGGGHTS output file '" + logDir_ + name +
                              "' cannot be written (check the permissions of '" + logDir_ + "')";
    }
    raiseIfAny(comm_, problem);
}

LiggghtsDriver::LiggghtsDriver(MPI_Comm comm, const std::string& logDir) : logDir_(logDir) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised)
        fail<Error>("LiggghtsDriver: MPI must be initialised before opening LIGGGHTS");
    MPI_Comm_dup(comm, &comm_);
    MPI_Comm_rank(comm_, &rank_);
    if (logDir_.empty()) logDir_ = ".";
    try {
        checkLogDir();
    } catch (...) {
        MPI_Comm_free(&comm_);
        throw;
    }

    std::string log = logDir_ + "/log.liggghts";
    std::string screen = logDir_ + "/screen.liggghts";
    // Not `-screen none`: that crashes LIGGGHTS 3.8.0 in Region::reset_random.
    const char* args[] = {"liggghts", "-log", log.c_str(), "-screen", screen.c_str()};
    constexpr int nArgs = sizeof(args) / sizeof(args[0]);
    void* handle = nullptr;
    lammps_open(nArgs, const_cast<char**>(args), comm, &handle);
    lmp_ = static_cast<LAMMPS_NS::LAMMPS*>(handle);
    // granair's own fix style, known before any script line runs (a script
    // may define the fluid-force fix itself).
    registerFluidForceFix(lmp_);

    // Route LIGGGHTS' screen through the ERROR-echoing stream on every rank
    // (on rank 0 it wraps the screen file; elsewhere the screen is NULL and
    // Error::one's message would otherwise be lost). universe->uscreen is
    // the same stream in a single-partition run.
    screen_ = openScreenErrorEcho(lmp_->screen, &lmp_->logfile, log, screen);
    if (screen_) {
        lmp_->screen = screen_;
        lmp_->universe->uscreen = screen_;
    }
}

LiggghtsDriver::~LiggghtsDriver() {
    // forces_ outlives LIGGGHTS: fix external holds a pointer to it.
    // LAMMPS' destructor closes the log but, in a single-partition run, not
    // the screen: close our stream (and the file under it) ourselves.
    lammps_close(lmp_);
    if (screen_) std::fclose(screen_);
    MPI_Comm_free(&comm_);
}

void LiggghtsDriver::runFile(const std::string& path) {
    // LIGGGHTS opens the script on rank 0 only and MPI_Aborts if it cannot.
    std::string problem;
    if (rank_ == 0) {
        std::FILE* f = std::fopen(path.c_str(), "r");
        if (f)
            std::fclose(f);
        else
            problem = "LIGGGHTS input script '" + path + "' cannot be read (missing file?)";
    }
    raiseIfAny(comm_, problem);
    needsSetup_ = true;
    lammps_file(lmp_, path.c_str());
}

void LiggghtsDriver::command(const std::string& line) {
    needsSetup_ = true;
    lammps_command(lmp_, line.c_str());
}

double LiggghtsDriver::timestep() const { return lmp_->update->dt; }

std::int64_t LiggghtsDriver::step() const { return lmp_->update->ntimestep; }

double LiggghtsDriver::time() const {
    return aligned_ ? alignedTime_ + static_cast<double>(step() - alignedStep_) * timestep()
                    : lmp_->update->get_cur_time();
}

void LiggghtsDriver::alignTime(double t) {
    aligned_ = true;
    alignedTime_ = t;
    alignedStep_ = step();
}

std::int64_t LiggghtsDriver::nGlobal() const {
    // Not atom->natoms: LIGGGHTS only refreshes it at thermo output when atoms
    // are lost with `thermo_modify lost ignore`.
    long long local = lmp_->atom->nlocal, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_LONG_LONG, MPI_SUM, comm_);
    return global;
}

int LiggghtsDriver::nLocal() const { return lmp_->atom->nlocal; }

void LiggghtsDriver::enableFluidForces() {
    if (forces_) return;
    forces_ = std::make_unique<FluidForceStore>(lmp_);
    needsSetup_ = true;
}

void LiggghtsDriver::setFluidForces(const std::vector<Vec3>& forces) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three contiguous doubles");
    setFluidForces(forces.empty() ? nullptr : forces.front().data(), forces.size());
}

std::string LiggghtsDriver::findLastParticles() {
    // Still in the remembered order? (Nothing ran since getParticles, unless a
    // command deleted or created atoms.) Otherwise match by tag.
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const int nlocal = atom.nlocal;
    lastIndex_.clear();
    bool sameOrder = nlocal == static_cast<int>(lastTags_.size());
    for (int i = 0; sameOrder && i < nlocal; ++i) sameOrder = atom.tag[i] == lastTags_[i];
    if (sameOrder) return {};
    std::unordered_map<int, int> local;
    local.reserve(nlocal);
    for (int i = 0; i < nlocal; ++i) local.emplace(atom.tag[i], i);
    lastIndex_.resize(lastTags_.size());
    for (std::size_t k = 0; k < lastTags_.size(); ++k) {
        auto it = local.find(lastTags_[k]);
        if (it == local.end()) {
            std::ostringstream problem;
            problem << "setFluidForces: particle " << lastTags_[k]
                    << " of the last getParticles() call is no longer on this rank "
                       "(deleted, or LIGGGHTS ran in between); call getParticles() again";
            return problem.str();
        }
        lastIndex_[k] = it->second;
    }
    return {};
}

void LiggghtsDriver::setFluidForces(const double* xyz, std::size_t n) {
    if (!forces_) fail<Error>("LiggghtsDriver::setFluidForces called before enableFluidForces()");
    std::string problem;
    if (n != lastTags_.size()) problem = forceCountProblem(n, lastTags_.size());
    for (std::size_t k = 0; problem.empty() && k < n; ++k)
        if (!allFinite3(xyz + 3 * k)) problem = nonFiniteForceProblem(lastTags_[k], xyz + 3 * k);
    if (problem.empty()) problem = findLastParticles();
    raiseIfAny(comm_, problem);
    for (std::size_t k = 0; k < n; ++k) storeForce(localIndex(k), xyz + 3 * k);
}

void LiggghtsDriver::storeForce(int i, const double* f) {
    // `run N pre no` does not recompute forces before its first half-kick:
    // it uses atom->f as the last step left it, which holds the *old* fluid
    // force. Patch f by the change so the new force acts from the first
    // half-step, exactly as a full setup would give (the other forces are
    // unchanged since nothing moved). A full setup recomputes f anyway, and
    // before the first run f holds nothing yet.
    double* fi = lmp_->atom->f[i];
    double* stored = forces_->force(i);
    for (int d = 0; d < 3; ++d) {
        if (!needsSetup_) fi[d] += f[d] - stored[d];
        stored[d] = f[d];
    }
}

void LiggghtsDriver::beginFluidForces() {
    if (!forces_) fail<Error>("LiggghtsDriver::beginFluidForces called before enableFluidForces()");
    // Not collective: a particle that is gone is raised by endFluidForces()
    // (one reduction per coupling step), and nothing is stored until then.
    forcesSet_ = 0;
    forceProblem_ = findLastParticles();
}

void LiggghtsDriver::setFluidForce(std::size_t k, const double* f) {
    ++forcesSet_;
    if (k >= lastTags_.size() || !allFinite3(f) || !forceProblem_.empty()) {
        if (forceProblem_.empty() && k >= lastTags_.size()) {
            std::ostringstream problem;
            problem << "setFluidForce: particle index " << k << " given for the "
                    << lastTags_.size() << " particles of the last getParticles() call on this rank";
            forceProblem_ = problem.str();
        } else if (forceProblem_.empty()) {
            forceProblem_ = nonFiniteForceProblem(lastTags_[k], f);
        }
        return;
    }
    storeForce(localIndex(k), f);
}

void LiggghtsDriver::endFluidForces() {
    if (forceProblem_.empty() && forcesSet_ != lastTags_.size())
        forceProblem_ = forceCountProblem(forcesSet_, lastTags_.size());
    std::string problem;
    std::swap(problem, forceProblem_);
    raiseIfAny(comm_, problem);
}

void LiggghtsDriver::getFluidForces(std::vector<double>& xyz) {
    if (!forces_) fail<Error>("LiggghtsDriver::getFluidForces called before enableFluidForces()");
    raiseIfAny(comm_, findLastParticles());
    xyz.resize(3 * lastTags_.size());
    for (std::size_t k = 0; k < lastTags_.size(); ++k) {
        const double* stored = forces_->force(localIndex(k));
        std::copy_n(stored, 3, xyz.data() + 3 * k);
    }
}

void LiggghtsDriver::advance(int nSteps) {
    if (nSteps < 0)
        fail<InputError>("LiggghtsDriver::advance: nSteps = ", nSteps, ", expected >= 0");
    if (forces_) forces_->bind();
    std::string cmd = "run " + std::to_string(nSteps);
    // A full setup re-initialises every style and rebuilds neighbour lists:
    // needed the first time and after any command (deleted or created atoms
    // invalidate the lists); `pre no` skips it for plain continuation, `post
    // no` skips the timing summary.
    if (!needsSetup_) cmd += " pre no post no";
    lammps_command(lmp_, cmd.c_str());
    needsSetup_ = false;
}

const ParticleList& LiggghtsDriver::particles() {
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    requireSpheres(atom);
    const int nlocal = atom.nlocal;
    // Grown by an eighth, not doubled, when this rank's particles grow (they
    // move between ranks): the memory report counts capacities (CapacityBytes.hpp).
    reserveGrowing(lastTags_, static_cast<std::size_t>(nlocal));
    lastTags_.assign(atom.tag, atom.tag + nlocal);
    const LAMMPS_NS::Domain& domain = *lmp_->domain;
    local_.lmp_ = lmp_;
    local_.n_ = static_cast<std::size_t>(nlocal);
    local_.periodic_ = domain.xperiodic || domain.yperiodic || domain.zperiodic;
    local_.triclinic_ = domain.triclinic != 0;
    const int periodic[3] = {domain.xperiodic, domain.yperiodic, domain.zperiodic};
    for (int d = 0; d < 3; ++d) {
        local_.lo_[d] = periodic[d] ? domain.boxlo[d] : -std::numeric_limits<double>::infinity();
        local_.hi_[d] = periodic[d] ? domain.boxhi[d] : std::numeric_limits<double>::infinity();
    }
    return local_;
}

ParticleState LiggghtsDriver::LocalParticles::operator[](std::size_t i) const {
    // The one-field reads below, together (the class is final: direct calls).
    ParticleState p;
    p.id = id(i);
    p.x = position(i);
    p.v = velocity(i);
    p.radius = radius(i);
    return p;
}

Vec3 LiggghtsDriver::LocalParticles::position(std::size_t i) const {
    const double* xi = lmp_->atom->x[i];
    double x[3] = {xi[0], xi[1], xi[2]};
    // In a periodic box LIGGGHTS wraps a particle that crossed a periodic
    // face only at the next re-neighbouring, so in between its centre may lie
    // up to half the skin outside the box (and outside the CFD mesh, which
    // covers the box). Report the wrapped position, as LIGGGHTS will hold it.
    // Domain::remap leaves an orthogonal box's inside point as it is (its
    // loops do not run, max(x, lo) = x): only the few outside call it. A
    // non-finite centre is left as it is: remap's MAX(x, lo) would turn a NaN
    // along a periodic dimension into lo, hiding it from the exchange's check
    // (which names the particle and the value).
    if (periodic_ && (triclinic_ || !(x[0] >= lo_[0] && x[0] < hi_[0] && x[1] >= lo_[1] && x[1] < hi_[1] &&
                                      x[2] >= lo_[2] && x[2] < hi_[2])) &&
        allFinite3(x))
        lmp_->domain->remap(x);
    return Vec3(x[0], x[1], x[2]);
}

std::int64_t LiggghtsDriver::LocalParticles::id(std::size_t i) const { return lmp_->atom->tag[i]; }

double LiggghtsDriver::LocalParticles::radius(std::size_t i) const { return lmp_->atom->radius[i]; }

Vec3 LiggghtsDriver::LocalParticles::velocity(std::size_t i) const {
    const double* v = lmp_->atom->v[i];
    return Vec3(v[0], v[1], v[2]);
}

void LiggghtsDriver::getParticles(std::vector<ParticleState>& out) {
    const ParticleList& list = particles();
    reserveGrowing(out, list.size());
    out.resize(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) out[i] = list[i];
}

void LiggghtsDriver::getParticleMasses(std::vector<double>& out) const {
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    requireSpheres(atom);
    out.assign(atom.rmass, atom.rmass + atom.nlocal);
}

std::array<int, 3> LiggghtsDriver::processorGrid() const {
    const LAMMPS_NS::Comm& c = *lmp_->comm;
    return {c.procgrid[0], c.procgrid[1], c.procgrid[2]};
}

std::vector<std::int64_t> LiggghtsDriver::particlesPerRank() const {
    int size = 1;
    MPI_Comm_size(comm_, &size);
    long long mine = lmp_->atom->nlocal;
    std::vector<long long> all(static_cast<std::size_t>(size));
    MPI_Allgather(&mine, 1, MPI_LONG_LONG, all.data(), 1, MPI_LONG_LONG, comm_);
    return std::vector<std::int64_t>(all.begin(), all.end());
}

LiggghtsDriver::NeighbourBins LiggghtsDriver::neighbourBins() const {
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    double rmax = 0;
    if (atom.radius)
        for (int i = 0; i < atom.nlocal; ++i) rmax = std::max(rmax, atom.radius[i]);
    MPI_Allreduce(MPI_IN_PLACE, &rmax, 1, MPI_DOUBLE, MPI_MAX, comm_);
    const LAMMPS_NS::Neighbor& n = *lmp_->neighbor;
    NeighbourBins b;
    b.cutoff = 2 * rmax + n.skin;
    b.userBinSize = NeighborInternals::userBinSize(n);
    b.binSize = b.userBinSize ? NeighborInternals::binSize(n) : 0.5 * b.cutoff;
    double bins = 0;
    if (b.binSize > 0) {
        bins = 1;
        const LAMMPS_NS::Domain& d = *lmp_->domain;
        for (int a = 0; a < 3; ++a) bins *= std::ceil((d.subhi[a] - d.sublo[a] + 2 * b.cutoff) / b.binSize);
    }
    struct {
        double bins;
        int rank;
    } mine{bins, rank_}, most{};
    MPI_Allreduce(&mine, &most, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_);
    b.bins = most.bins;
    b.rank = most.rank;
    long long there = rank_ == most.rank ? atom.nlocal : 0;
    MPI_Allreduce(MPI_IN_PLACE, &there, 1, MPI_LONG_LONG, MPI_SUM, comm_);
    b.particlesThere = there;
    return b;
}

}  // namespace granair::dem
