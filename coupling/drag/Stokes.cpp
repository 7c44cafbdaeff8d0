// Stokes.cpp: see Stokes.hpp.
#include "drag/Stokes.hpp"

#include <cmath>

#include "drag/DragInputCheck.hpp"

namespace granair {

std::unique_ptr<DragLaw> Stokes::fromDictionary(const Dictionary&) { return std::make_unique<Stokes>(); }

double Stokes::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    return 3.0 * M_PI * f.mu * d;
}

}  // namespace granair
