// DischargeCounter.hpp: mass balance of a silo discharge in LIGGGHTS.
//
// Particles move down (-z). At each update() (call it after advance()):
//   * a particle the counter has not seen before counts as inserted;
//   * a particle whose centre is below the outlet plane (z < zOutlet) for the
//     first time counts as discharged, exactly once;
//   * particles at or below the sink level (z <= zSink <= zOutlet) are deleted
//     from LIGGGHTS and count as removed (they were discharged already).
// Balance: inserted = present + removed + lost, where lost is everything that
// vanished otherwise (LIGGGHTS drops particles that leave a non-periodic box
// when `thermo_modify lost ignore` is set, ...): a non-zero lost is a fault
// in the case set-up, and report() says so loudly.
//
// What "seen" and "discharged" mean lives with each particle in a LIGGGHTS
// per-atom property (fix granairDischargeState property/atom, 0 = not yet
// seen, 1 = seen, 2 = discharged), which moves with the particle between
// ranks and is 0 for every newly created particle. Tags are not used to find
// new particles: LIGGGHTS' Atom::tag_extend gives new particles tags above
// the largest *present* tag, so tags of deleted particles can come back. Such
// reuse is counted (reusedTags) because the coupling layer keys on tags.
// Sampling: crossings are seen at update() times only; a particle inserted
// and lost between two updates is in none of the counts.
#pragma once
#include <cstdint>
#include <ostream>

namespace LAMMPS_NS {
class Fix;
}

namespace granair::dem {

class LiggghtsDriver;

// Global (all ranks) counts and masses [kg] since the counter was created.
struct DischargeBalance {
    std::int64_t inserted = 0, present = 0, discharged = 0, removed = 0, lost = 0;
    double insertedMass = 0, presentMass = 0, dischargedMass = 0, removedMass = 0, lostMass = 0;
    std::int64_t reusedTags = 0;  // new particles whose tag an earlier particle had
};

class DischargeCounter {
public:
    static constexpr const char* stateFixId = "granairDischargeState";

    // zOutlet, zSink [m]: InputError unless finite with zSink <= zOutlet.
    // Collective (creates the per-atom property and the sink region).
    DischargeCounter(LiggghtsDriver& driver, double zOutlet, double zSink);

    // Count new and discharged particles, delete those at the sink.
    // Collective. After a deletion the next advance() does a full LIGGGHTS
    // setup (neighbour lists are rebuilt).
    void update();

    const DischargeBalance& balance() const { return balance_; }
    // A restart: the counts up to the restart point (the per-particle
    // states come back with LIGGGHTS' restart file). maxTagSeen: the largest
    // tag seen so far (for the reused-tag count).
    void restore(const DischargeBalance& balance, std::int64_t maxTagSeen);
    std::int64_t maxTagSeen() const { return maxTagSeen_; }
    double zOutlet() const { return zOutlet_; }
    double zSink() const { return zSink_; }

    // Prints the balance on rank 0 of the driver's communicator (other ranks
    // print nothing); a non-zero lost count is flagged on its own line.
    void report(std::ostream& os) const;

private:
    LiggghtsDriver& driver_;
    double zOutlet_, zSink_;
    DischargeBalance balance_;
    std::int64_t maxTagSeen_ = 0;
};

}  // namespace granair::dem
