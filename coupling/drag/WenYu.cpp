// WenYu.cpp: see WenYu.hpp.
#include "drag/WenYu.hpp"

#include <cmath>

#include "drag/DragInputCheck.hpp"
#include "drag/SchillerNaumann.hpp"

namespace granair {

std::unique_ptr<DragLaw> WenYu::fromDictionary(const Dictionary&) { return std::make_unique<WenYu>(); }

double WenYu::coefficient(double d, double eps, double slip, const FluidProperties& f) {
    const double Re = eps * f.rho * d * slip / f.mu;
    return M_PI / 8.0 * f.mu * d * schillerNaumannCdRe(Re) * std::pow(eps, -2.65);
}

double WenYu::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    return coefficient(d, eps, slip, f);
}

}  // namespace granair
