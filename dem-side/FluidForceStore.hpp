// FluidForceStore.hpp: the per-particle fluid force inside LIGGGHTS, held
// constant until set again and added to each particle's force every step.
//
// Two fixes, created if the script has not defined them:
//   fix granairFluidForce all property/atom granairFluidForce vector no no no 0 0 0
//       the stored force [N] per particle: a per-atom array that LIGGGHTS
//       moves with the particle (exchange between ranks, sorting, deletion)
//       and sets to (0,0,0) for every newly created particle;
//   fix granair_fluid all external pf/callback 1 1
//       every step calls our callback, which copies the stored force into the
//       fix's own array fexternal, which it then adds to f.
// Why not write fexternal directly: FixExternal has no set_arrays(), so a
// particle created by insertion inherits whatever force the array slot held
// (the last particle that used it, or uninitialised memory after a grow).
// If the script defines granair_fluid itself it must be `pf/callback 1 1`
// (ncall 1: the copy must run every step).
#pragma once
#include <cstdint>

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
class FixExternal;
}  // namespace LAMMPS_NS

namespace granair::dem {

class FluidForceStore {
public:
    static constexpr const char* propertyFixId = "granairFluidForce";
    static constexpr const char* externalFixId = "granair_fluid";

    // Creates the fixes if missing and installs the callback. Collective
    // over the LIGGGHTS communicator (issues LIGGGHTS commands).
    explicit FluidForceStore(LAMMPS_NS::LAMMPS* lmp);

    // Find both fixes again and re-install the callback: a script command
    // may have re-created them. Throws granair::Error if either is missing
    // or of the wrong style. Call before every run.
    void bind();

    // Stored force of local particle i (0 <= i < nlocal) [N].
    double* force(int i);

private:
    // FixExternal::FnPtr (bigint == std::int64_t in the Debian build).
    static void copyToExternal(void* self, std::int64_t step, int nlocal, int* tag,
                               double** x, double** fexternal);

    LAMMPS_NS::LAMMPS* lmp_;
    LAMMPS_NS::Fix* property_ = nullptr;
    LAMMPS_NS::FixExternal* external_ = nullptr;
};

}  // namespace granair::dem
