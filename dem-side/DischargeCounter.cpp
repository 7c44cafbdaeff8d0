// DischargeCounter.cpp: see DischargeCounter.hpp.
#include "DischargeCounter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "LiggghtsDriver.hpp"
#include "LiggghtsFixes.hpp"
#include "atom.h"
#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "fix.h"
#include "lammps.h"

namespace granair::dem {

namespace {

constexpr const char* sinkRegionId = "granairSink";

// Per-particle states held in the property fix.
constexpr double notSeen = 0.0, seen = 1.0, discharged = 2.0;

// %.17g: the region bound LIGGGHTS parses back is the same double as ours,
// so its "inside" test (z <= zhi) and ours agree bit for bit.
std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

}  // namespace

DischargeCounter::DischargeCounter(LiggghtsDriver& driver, double zOutlet, double zSink)
    : driver_(driver), zOutlet_(zOutlet), zSink_(zSink) {
    if (!std::isfinite(zOutlet) || !std::isfinite(zSink) || zSink > zOutlet)
        fail<InputError>("DischargeCounter: zOutlet = ", zOutlet, " m, zSink = ", zSink,
                         " m; expected finite values with zSink <= zOutlet (particles move "
                         "down through the outlet, then reach the sink)");
    ensurePropertyAtom(driver_.lammps(), stateFixId, 1, notSeen);
    // Region used by delete_atoms: inside == z <= zSink (RegBlock::inside).
    driver_.command(std::string("region ") + sinkRegionId + " block INF INF INF INF INF " +
                    exact(zSink_) + " units box");
}

void DischargeCounter::update() {
    LAMMPS_NS::LAMMPS* lmp = driver_.lammps();
    LAMMPS_NS::Fix* stateFix = findFix(lmp, stateFixId, "property/atom");
    if (!stateFix)
        fail<Error>("LIGGGHTS fix '", stateFixId,
                    "' (discharge state) has disappeared: scripts must not unfix granair's fixes");
    const LAMMPS_NS::Atom& atom = *lmp->atom;
    const int nlocal = atom.nlocal;
    double* state = stateFix->vector_atom;

    // Local sums: counts as long long, masses as double.
    enum { kNew, kReused, kDischarged, kSink, kPresent, nCounts };
    enum { mNew, mDischarged, mSink, mPresent, nMasses };
    long long counts[nCounts] = {0, 0, 0, 0, 0};
    double masses[nMasses] = {0, 0, 0, 0};
    long long maxTag = 0;
    for (int i = 0; i < nlocal; ++i) {
        const double m = atom.rmass[i];
        const double z = atom.x[i][2];
        const int tag = atom.tag[i];
        if (state[i] == notSeen) {
            ++counts[kNew];
            masses[mNew] += m;
            if (tag <= maxTagSeen_) ++counts[kReused];
            state[i] = seen;
        }
        const bool atSink = z <= zSink_;
        // atSink too: with zSink == zOutlet a particle exactly on the plane is
        // removed, so it must be counted as discharged first.
        if (state[i] != discharged && (z < zOutlet_ || atSink)) {
            ++counts[kDischarged];
            masses[mDischarged] += m;
            state[i] = discharged;
        }
        if (atSink) {
            ++counts[kSink];
            masses[mSink] += m;
        } else {
            ++counts[kPresent];
            masses[mPresent] += m;
        }
        maxTag = std::max<long long>(maxTag, tag);
    }
    long long globalCounts[nCounts];
    double globalMasses[nMasses];
    long long globalMaxTag = 0;
    MPI_Comm comm = driver_.comm();
    MPI_Allreduce(counts, globalCounts, nCounts, MPI_LONG_LONG, MPI_SUM, comm);
    MPI_Allreduce(masses, globalMasses, nMasses, MPI_DOUBLE, MPI_SUM, comm);
    MPI_Allreduce(&maxTag, &globalMaxTag, 1, MPI_LONG_LONG, MPI_MAX, comm);

    if (globalCounts[kSink] > 0) {
        // compress no: the remaining particles keep their tags.
        driver_.command(std::string("delete_atoms region ") + sinkRegionId + " compress no");
        // delete_atoms removes exactly the local particles inside the region
        // on each rank (no migration happens in between): check it did.
        std::string problem;
        if (lmp->atom->nlocal != nlocal - counts[kSink])
            problem = "DischargeCounter: delete_atoms removed " +
                      std::to_string(nlocal - lmp->atom->nlocal) + " particles on this rank, " +
                      std::to_string(counts[kSink]) + " were at or below zSink = " +
                      exact(zSink_) + " m";
        raiseIfAny(comm, problem);
    }

    DischargeBalance& b = balance_;
    b.inserted += globalCounts[kNew];
    b.insertedMass += globalMasses[mNew];
    b.reusedTags += globalCounts[kReused];
    b.discharged += globalCounts[kDischarged];
    b.dischargedMass += globalMasses[mDischarged];
    b.removed += globalCounts[kSink];
    b.removedMass += globalMasses[mSink];
    b.present = globalCounts[kPresent];
    b.presentMass = globalMasses[mPresent];
    b.lost = b.inserted - b.present - b.removed;
    // Exact for the counts; for the masses only to round-off of the sums.
    b.lostMass = b.insertedMass - b.presentMass - b.removedMass;
    maxTagSeen_ = std::max<std::int64_t>(maxTagSeen_, globalMaxTag);
}

void DischargeCounter::restore(const DischargeBalance& balance, std::int64_t maxTagSeen) {
    balance_ = balance;
    maxTagSeen_ = maxTagSeen;
}

void DischargeCounter::report(std::ostream& os) const {
    if (driver_.rank() != 0) return;
    const DischargeBalance& b = balance_;
    char line[200];
    auto row = [&](const char* what, std::int64_t n, double m) {
        std::snprintf(line, sizeof line, "  %-40s %12lld  %14.6e kg\n", what,
                      static_cast<long long>(n), m);
        os << line;
    };
    os << "DEM discharge balance at step " << driver_.step() << " (t = " << driver_.time()
       << " s), outlet z < " << zOutlet_ << " m, sink z <= " << zSink_ << " m\n";
    row("inserted", b.inserted, b.insertedMass);
    row("present", b.present, b.presentMass);
    row("removed at the sink", b.removed, b.removedMass);
    row("lost (inserted - present - removed)", b.lost, b.lostMass);
    row("discharged (crossed the outlet)", b.discharged, b.dischargedMass);
    if (b.lost != 0)
        os << "  *** LOST PARTICLES: " << b.lost << " particle(s) (" << b.lostMass
           << " kg) vanished without reaching the sink: they left the box or were deleted by "
              "the script; check the walls and `thermo_modify lost` ***\n";
    if (b.reusedTags != 0)
        os << "  note: " << b.reusedTags
           << " new particle(s) got the tag of a deleted one (LIGGGHTS reuses tags above the "
              "largest present tag)\n";
    os.flush();
}

}  // namespace granair::dem
