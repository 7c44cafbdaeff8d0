// FluidForceFix.hpp: the LIGGGHTS fix that adds granair's stored fluid force
// to every particle's force each step.
//
//   fix granair_fluid all granair/fluidforce granairFluidForce
//
// The force lives in the named `property/atom` vector fix (3 values per
// particle; it moves with the particle between ranks, through sorting and
// restarts, and is zero for a new particle). This fix has no per-particle
// data of its own: its post_force adds that array to atom->f.
//
// Why not LIGGGHTS' `fix external pf/callback` (used until 2026-12): it keeps
// a second per-particle array, fexternal, with no set_arrays() (a new
// particle inherits the stale entry of its slot), so the store had to be
// copied into it by a callback every step before FixExternal added it to f:
// two passes over three arrays per particle-step, 3.1 % of the run's time on
// bench/coupled's 1e5-particle column (perf), against one pass here.
//
// The style is not in the Debian LIGGGHTS build: registerFluidForceFix()
// adds it to the instance's style table (Modify::fix_map) before the fix
// command is issued.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace granair::dem {

// The style name scripts and granair use.
constexpr const char* fluidForceFixStyle = "granair/fluidforce";

// Adds the granair/fluidforce style to this LIGGGHTS instance (idempotent).
void registerFluidForceFix(LAMMPS_NS::LAMMPS* lmp);

}  // namespace granair::dem
