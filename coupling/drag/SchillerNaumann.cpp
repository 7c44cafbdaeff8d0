// SchillerNaumann.cpp: see SchillerNaumann.hpp.
#include "drag/SchillerNaumann.hpp"

#include "drag/DragInputCheck.hpp"

namespace granair {

std::unique_ptr<DragLaw> SchillerNaumann::fromDictionary(const Dictionary&) {
    return std::make_unique<SchillerNaumann>();
}

double SchillerNaumann::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    const double Re = f.rho * d * slip / f.mu;
    // (pi/8) Cd rho d^2 |u| with Cd rho d |u| = Cd Re mu.
    return M_PI / 8.0 * f.mu * d * schillerNaumannCdRe(Re);
}

}  // namespace granair
