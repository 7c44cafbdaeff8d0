// DragInputCheck.hpp: the input check every drag law runs before it computes.
//
// A drag law is evaluated per particle with values interpolated from the air
// solver; a NaN or an out-of-range void fraction there means something went
// wrong upstream, and it must surface as an InputError naming the bad value
// rather than as a NaN force. The message starts with what was wrong, e.g.
//     drag law ErgunGidaspow: void fraction 1.3 outside (0, 1]
// so the caller can append the particle id.
#pragma once
#include "core/Particle.hpp"

namespace granair {

// Throws InputError unless d > 0, 0 < eps <= 1, slip >= 0, rho > 0, mu > 0,
// all finite. lawName only goes into the message.
// lawName: the law's typeName. Called per particle and coupling step: it
// builds no string unless an input is bad.
void checkDragInput(const char* lawName, double d, double eps, double slip, const FluidProperties& f);

}  // namespace granair
