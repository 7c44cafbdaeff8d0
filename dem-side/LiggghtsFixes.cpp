// LiggghtsFixes.cpp: see LiggghtsFixes.hpp.
#include "LiggghtsFixes.hpp"

#include <sstream>

#include "core/Error.hpp"
#include "fix.h"
#include "library.h"
#include "lammps.h"
#include "modify.h"

namespace granair::dem {

LAMMPS_NS::Fix* findFix(LAMMPS_NS::LAMMPS* lmp, const std::string& id, const std::string& style) {
    LAMMPS_NS::Fix* fix = lmp->modify->find_fix_id(id.c_str());
    if (fix && style != fix->style)
        fail<Error>("LIGGGHTS fix '", id, "' has style '", fix->style,
                    "' but granair needs style '", style,
                    "' under this id (the id is reserved for granair)");
    return fix;
}

LAMMPS_NS::Fix* ensurePropertyAtom(LAMMPS_NS::LAMMPS* lmp, const std::string& id, int columns,
                                   double defaultValue) {
    LAMMPS_NS::Fix* fix = findFix(lmp, id, "property/atom");
    if (!fix) {
        std::ostringstream cmd;
        cmd.precision(17);
        cmd << "fix " << id << " all property/atom " << id << (columns == 1 ? " scalar" : " vector")
            << " yes no no";  // restart yes, no ghost communication
        for (int c = 0; c < columns; ++c) cmd << ' ' << defaultValue;
        lammps_command(lmp, cmd.str().c_str());
        fix = findFix(lmp, id, "property/atom");
    }
    // size_peratom_cols is 0 for a scalar (vector_atom), N for N columns.
    const int cols = columns == 1 ? 0 : columns;
    if (!fix || fix->size_peratom_cols != cols)
        fail<Error>("LIGGGHTS fix '", id, "' must be a property/atom with ", columns,
                    " value(s) per particle");
    // The constructor has already set every existing particle to the default;
    // left "just created", the next run's setup would reset all of them
    // again, wiping values granair wrote before that run (LIGGGHTS' own
    // fixes clear the flag for the same reason).
    fix->just_created = 0;
    return fix;
}

}  // namespace granair::dem
