// FluidForceStore.cpp: see FluidForceStore.hpp.
#include "FluidForceStore.hpp"

#include <string>

#include "FluidForceFix.hpp"
#include "LiggghtsFixes.hpp"
#include "core/Error.hpp"
#include "fix.h"
#include "lammps.h"
#include "library.h"

namespace granair::dem {

FluidForceStore::FluidForceStore(LAMMPS_NS::LAMMPS* lmp) : lmp_(lmp) {
    // The store first: the force fix reads it.
    ensurePropertyAtom(lmp_, propertyFixId, 3, 0.0);
    if (!findFix(lmp_, forceFixId, fluidForceFixStyle)) {
        const std::string cmd = std::string("fix ") + forceFixId + " all " + fluidForceFixStyle + " " + propertyFixId;
        lammps_command(lmp_, cmd.c_str());
    }
    bind();
}

void FluidForceStore::bind() {
    property_ = findFix(lmp_, propertyFixId, "property/atom");
    LAMMPS_NS::Fix* apply = findFix(lmp_, forceFixId, fluidForceFixStyle);
    if (!property_ || !apply)
        fail<Error>("LIGGGHTS fix '", property_ ? forceFixId : propertyFixId,
                    "' (fluid forces) has disappeared: scripts must not unfix granair's fixes");
}

double* FluidForceStore::force(int i) { return property_->array_atom[i]; }

}  // namespace granair::dem
