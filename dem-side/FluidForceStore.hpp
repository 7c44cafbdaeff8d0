// FluidForceStore.hpp: the per-particle fluid force inside LIGGGHTS, held
// constant until set again and added to each particle's force every step.
//
// Two fixes, created if the script has not defined them:
//   fix granairFluidForce all property/atom granairFluidForce vector yes no no 0 0 0
//       the stored force [N] per particle: a per-atom array that LIGGGHTS
//       moves with the particle (exchange between ranks, sorting, deletion,
//       restart files) and sets to (0,0,0) for every newly created particle;
//   fix granair_fluid all granair/fluidforce granairFluidForce
//       granair's own fix (FluidForceFix.hpp): every step adds the stored
//       force to f. If the script defines granair_fluid itself it must be
//       of that style.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}  // namespace LAMMPS_NS

namespace granair::dem {

class FluidForceStore {
public:
    static constexpr const char* propertyFixId = "granairFluidForce";
    static constexpr const char* forceFixId = "granair_fluid";

    // Creates the fixes if missing. Collective over the LIGGGHTS
    // communicator (issues LIGGGHTS commands). The granair/fluidforce style
    // must be known to lmp: LiggghtsDriver registers it when it opens LIGGGHTS.
    explicit FluidForceStore(LAMMPS_NS::LAMMPS* lmp);

    // Find both fixes again: a script command may have re-created them.
    // Throws granair::Error if either is missing or of the wrong style.
    // Call before every run.
    void bind();

    // Stored force of local particle i (0 <= i < nlocal) [N].
    double* force(int i);

private:
    LAMMPS_NS::LAMMPS* lmp_;
    LAMMPS_NS::Fix* property_ = nullptr;
};

}  // namespace granair::dem
