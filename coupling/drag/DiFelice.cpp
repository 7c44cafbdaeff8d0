// DiFelice.cpp: see DiFelice.hpp.
#include "drag/DiFelice.hpp"

#include <cmath>

#include "drag/DragInputCheck.hpp"

namespace granair {

std::unique_ptr<DragLaw> DiFelice::fromDictionary(const Dictionary&) { return std::make_unique<DiFelice>(); }

double DiFelice::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    const double Re = f.rho * d * eps * slip / f.mu;
    // chi -> 3.7 as Re -> 0 (log10 Re -> -inf); take the limit explicitly.
    const double chi = Re > 0 ? 3.7 - 0.65 * std::exp(-0.5 * std::pow(1.5 - std::log10(Re), 2)) : 3.7;
    const double sqrtCdRe = 0.63 * std::sqrt(Re) + 4.8;
    return M_PI / 8.0 * f.mu * d * std::pow(eps, 1.0 - chi) * sqrtCdRe * sqrtCdRe;
}

}  // namespace granair
