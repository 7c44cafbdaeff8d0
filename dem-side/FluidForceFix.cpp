// FluidForceFix.cpp: see FluidForceFix.hpp.
#include "FluidForceFix.hpp"

#include <map>
#include <string>

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

namespace granair::dem {

namespace {

class FluidForceFix : public LAMMPS_NS::Fix {
public:
    // fix ID group granair/fluidforce PROPERTY_ID
    FluidForceFix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
        if (narg != 4)
            error->all(FLERR, "Illegal fix granair/fluidforce command: expected "
                              "'fix ID group granair/fluidforce PROPERTY_ID' (the property/atom "
                              "vector fix holding the force)");
        propertyId_ = arg[3];
    }

    int setmask() override { return LAMMPS_NS::FixConst::POST_FORCE; }

    // Every `run` (with or without its setup) calls init: find the store
    // again, a script may have re-defined it.
    void init() override {
        property_ = modify->find_fix_id(propertyId_.c_str());
        if (!property_ || std::string(property_->style) != "property/atom" ||
            property_->size_peratom_cols != 3)
            error->all(FLERR, ("fix granair/fluidforce: fix '" + propertyId_ +
                               "' must be a property/atom vector with 3 values per particle")
                                  .c_str());
    }

    void setup(int vflag) override { post_force(vflag); }

    void post_force(int) override {
        // Through the fix every step: LIGGGHTS reallocates the array when
        // this rank's particles outgrow it.
        double** stored = property_->array_atom;
        double** f = atom->f;
        const int* mask = atom->mask;
        const int nlocal = atom->nlocal;
        if (nlocal == 0) return;
        // LIGGGHTS' per-atom arrays are one block of rows (Memory::create and
        // grow), so for the group `all` (bit 1, in every atom's mask) this is
        // one flat loop over 3 nlocal doubles: no row pointers to load, no
        // mask to test, and it vectorises (perf, bench/coupled's 1e5 column
        // at 1 rank: 1.36 % of the run with the row loop below, 1.06 % flat;
        // what is left is streaming two 2.4 MB arrays through the cache).
        // Checked, not assumed: rows that are not one block take the loop below.
        if (groupbit == 1 && f[nlocal - 1] == f[0] + 3 * (nlocal - 1) &&
            stored[nlocal - 1] == stored[0] + 3 * (nlocal - 1)) {
            double* __restrict fFlat = f[0];
            const double* __restrict sFlat = stored[0];
            const int n = 3 * nlocal;
            for (int k = 0; k < n; ++k) fFlat[k] += sFlat[k];
            return;
        }
        for (int i = 0; i < nlocal; ++i) {
            if (!(mask[i] & groupbit)) continue;
            f[i][0] += stored[i][0];
            f[i][1] += stored[i][1];
            f[i][2] += stored[i][2];
        }
    }

private:
    std::string propertyId_;
    LAMMPS_NS::Fix* property_ = nullptr;
};

LAMMPS_NS::Fix* createFluidForceFix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
    return new FluidForceFix(lmp, narg, arg);
}

// Modify's table of fix styles (fix_map) is private in LIGGGHTS 3.8 and is
// filled from the styles compiled into the library; it has no public way to
// add one. An explicit template instantiation may name a private member
// (C++17 [temp.explicit]/12: access checking does not apply to it): Steal
// hands the member pointer to fixMapMember().
using FixStyleMap = std::map<std::string, LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**)>;
FixStyleMap* LAMMPS_NS::Modify::*fixMapMember();

template <FixStyleMap* LAMMPS_NS::Modify::*Member>
struct Steal {
    friend FixStyleMap* LAMMPS_NS::Modify::*fixMapMember() { return Member; }
};
template struct Steal<&LAMMPS_NS::Modify::fix_map>;

}  // namespace

void registerFluidForceFix(LAMMPS_NS::LAMMPS* lmp) {
    FixStyleMap& styles = *(lmp->modify->*fixMapMember());
    styles[fluidForceFixStyle] = &createFluidForceFix;
}

}  // namespace granair::dem
