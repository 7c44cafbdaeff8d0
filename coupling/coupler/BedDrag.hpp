// BedDrag.hpp: drag per unit volume of a bed of equal spheres.
//
// Where no particles are tracked (a prescribed static bed in granairAirFoam,
// the continuum granular solver) the bed is described by its void fraction
// eps and particle diameter d. It holds n = (1 - eps)/V_p particles per unit
// volume, each with the drag law's per-particle coefficient beta, so
//     K = beta(d, eps, slip) (1 - eps) / V_p      [kg/(m3 s)],   V_p = pi d^3/6
// which is exactly what the particle-based coupling step gives for a uniform
// bed, so a prescribed bed and a DEM bed see the same drag.
#pragma once

#include "drag/DragLaw.hpp"

namespace granair {

double bedMomentumExchange(const DragLaw& law, double d, double eps, double slip,
                           const FluidProperties& fluid);

}  // namespace granair
