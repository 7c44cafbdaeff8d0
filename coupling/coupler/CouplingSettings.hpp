// CouplingSettings.hpp: the coupling settings of a case, read from the case's
// constant/couplingProperties (one dictionary for everything the coupling
// layer needs; the air's own properties stay in OpenFOAM's files).
//
//   couplingInterval    50;          // DEM steps per CFD step (N), >= 1
//   air                 on;          // off: DEM-only reference run, same case
//   momentumCoupling    two-way;     // one-way: forces on the particles only;
//                                    // the air sees no particles (eps 1, no drag)
//   coarseGrainingFactor 1;          // parcel = s^3 primary particles, s >= 1
//   voidFractionFloor   0.3;         // eps is floored here (hits are counted)
//   gravity             (0 0 -9.81); // [m/s2], for the particles' buoyancy
//   forces { drag on; pressureGradient on; buoyancy on; applied on; }
//                                    // applied off (benchmarking): every force is
//                                    // computed and sent, LIGGGHTS is given 0
//   drag         { type ErgunGidaspow; ... }   // coupling/drag registry
//   voidFraction { type centre; ... }          // coupling/voidfraction registry
// drag and voidFraction are required with the air on; with it off they are
// optional (voidFraction, default centre, still maps the output void fraction).
#pragma once
#include <memory>

#include "core/Dictionary.hpp"
#include "drag/DragLaw.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

struct CouplingSettings {
    int couplingInterval = 1;
    bool airOn = true;
    bool oneWay = false;  // momentumCoupling one-way (MFiX's DES_ONEWAY_COUPLED, CFDEM's checks)
    double coarseGrainingFactor = 1.0;
    double voidFractionFloor = 0.3;
    Vec3 gravity{0, 0, -9.81};
    bool dragForce = true;
    bool pressureGradientForce = true;
    bool buoyancyForce = true;
    // false (`forces { applied off; }`): the fluid forces are computed, sent
    // back and written into LIGGGHTS' force store as zeros, so the DEM
    // integrates the same problem as `air off` while the coupling does all of
    // its work: the fair reference for the coupling's overhead (bench/README.md).
    bool forcesApplied = true;
    std::shared_ptr<const DragLaw> drag;
    std::shared_ptr<const VoidFractionModel> voidFraction;

    static CouplingSettings read(const Dictionary& dict);
};

}  // namespace granair
