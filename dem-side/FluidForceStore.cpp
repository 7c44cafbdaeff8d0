// FluidForceStore.cpp: see FluidForceStore.hpp.
#include "FluidForceStore.hpp"

#include <string>

#include "LiggghtsFixes.hpp"
#include "core/Error.hpp"
#include "fix_external.h"
#include "lammps.h"
#include "library.h"

namespace granair::dem {

FluidForceStore::FluidForceStore(LAMMPS_NS::LAMMPS* lmp) : lmp_(lmp) {
    // The property fix first: the external fix's callback reads it.
    ensurePropertyAtom(lmp_, propertyFixId, 3, 0.0);
    if (!findFix(lmp_, externalFixId, "external")) {
        const std::string cmd =
            std::string("fix ") + externalFixId + " all external pf/callback 1 1";
        lammps_command(lmp_, cmd.c_str());
    }
    bind();
}

void FluidForceStore::bind() {
    property_ = findFix(lmp_, propertyFixId, "property/atom");
    LAMMPS_NS::Fix* ext = findFix(lmp_, externalFixId, "external");
    if (!property_ || !ext)
        fail<Error>("LIGGGHTS fix '", property_ ? externalFixId : propertyFixId,
                    "' (fluid forces) has disappeared: scripts must not unfix granair's fixes");
    external_ = static_cast<LAMMPS_NS::FixExternal*>(ext);
    external_->set_callback(&FluidForceStore::copyToExternal, this);
}

double* FluidForceStore::force(int i) { return property_->array_atom[i]; }

void FluidForceStore::copyToExternal(void* self, std::int64_t, int nlocal, int*, double**,
                                     double** fexternal) {
    // Read the array through the fix every call: LIGGGHTS reallocates it
    // when the number of atoms on this rank grows.
    double** stored = static_cast<FluidForceStore*>(self)->property_->array_atom;
    for (int i = 0; i < nlocal; ++i) {
        fexternal[i][0] = stored[i][0];
        fexternal[i][1] = stored[i][1];
        fexternal[i][2] = stored[i][2];
    }
}

}  // namespace granair::dem
