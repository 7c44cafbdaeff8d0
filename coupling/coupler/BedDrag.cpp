// BedDrag.cpp: see BedDrag.hpp.
#include "coupler/BedDrag.hpp"

#include <cmath>

namespace granair {

double bedMomentumExchange(const DragLaw& law, double d, double eps, double slip,
                           const FluidProperties& fluid) {
    if (eps >= 1.0) return 0.0;  // no particles, no drag
    const double vp = M_PI * d * d * d / 6.0;
    return law.beta(d, eps, slip, fluid) * (1.0 - eps) / vp;
}

}  // namespace granair
