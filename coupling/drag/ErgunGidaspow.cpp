// ErgunGidaspow.cpp: see ErgunGidaspow.hpp.
#include "drag/ErgunGidaspow.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "drag/DragInputCheck.hpp"
#include "drag/WenYu.hpp"

namespace granair {

ErgunGidaspow::ErgunGidaspow(double switchVoidFraction) : switch_(switchVoidFraction) {
    if (!(switch_ > 0 && switch_ <= 1))  // false for NaN too
        failParameter("switchVoidFraction", "drag law ", typeName, ": switchVoidFraction value ", switch_,
                      " outside (0, 1], expected the void fraction above which ", typeName,
                      " uses Wen-Yu instead of Ergun");
}

std::unique_ptr<DragLaw> ErgunGidaspow::fromDictionary(const Dictionary& dict) {
    return std::make_unique<ErgunGidaspow>(dict.getDouble("switchVoidFraction", defaultSwitchVoidFraction));
}

double ErgunGidaspow::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    if (eps >= switch_) return WenYu::coefficient(d, eps, slip, f);
    // Ergun per particle: [150 (1-eps)^2 mu/(eps d^2) + 1.75 (1-eps) rho |u|/d] * (pi d^3/6)/(1-eps)
    return 25.0 * M_PI * f.mu * d * (1.0 - eps) / eps + 7.0 * M_PI / 24.0 * f.rho * d * d * slip;
}

}  // namespace granair
