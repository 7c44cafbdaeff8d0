// LiggghtsFixes.hpp: finding the fixes granair creates inside LIGGGHTS, and
// the per-atom property fixes that carry granair's data with each particle.
#pragma once
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}  // namespace LAMMPS_NS

namespace granair::dem {

// The fix with this id, or nullptr if there is none. Throws granair::Error
// if it exists with another style (the script reused one of our ids).
LAMMPS_NS::Fix* findFix(LAMMPS_NS::LAMMPS* lmp, const std::string& id, const std::string& style);

// Ensure `fix <id> all property/atom <id> <scalar|vector> yes no no <defaults>`
// exists (columns 1: scalar, else vector of that many values, all defaulting
// to `defaultValue`), creating it if missing, and return it. New particles
// get the default (LIGGGHTS calls the fix's set_arrays on creation), the
// value moves with the particle between ranks and goes into restart files
// (`yes`): defined again after a read_restart, the fix takes the values
// back (LAMMPS' Modify::add_fix restores per-atom restart data of a fix
// with the same id and style). Collective.
LAMMPS_NS::Fix* ensurePropertyAtom(LAMMPS_NS::LAMMPS* lmp, const std::string& id, int columns,
                                   double defaultValue);

}  // namespace granair::dem
