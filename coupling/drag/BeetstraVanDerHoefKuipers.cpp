// BeetstraVanDerHoefKuipers.cpp: see BeetstraVanDerHoefKuipers.hpp.
#include "drag/BeetstraVanDerHoefKuipers.hpp"

#include <cmath>

#include "drag/DragInputCheck.hpp"

namespace granair {

std::unique_ptr<DragLaw> BeetstraVanDerHoefKuipers::fromDictionary(const Dictionary&) {
    return std::make_unique<BeetstraVanDerHoefKuipers>();
}

double BeetstraVanDerHoefKuipers::dimensionlessDrag(double eps, double Re) {
    const double phi = 1.0 - eps;
    const double eps2 = eps * eps;
    const double low = 10.0 * phi / eps2 + eps2 * (1.0 + 1.5 * std::sqrt(phi));
    // Re/(1 + 10^(3 phi) Re^-a) * (... + 8.4 Re^-0.343), multiplied through by
    // R = Re^a so that Re = 0 gives 0 instead of inf/inf.
    const double R = std::pow(Re, 0.5 * (1.0 + 4.0 * phi));
    const double numerator = Re * (1.0 / eps + 3.0 * eps * phi) + 8.4 * std::pow(Re, 0.657);
    const double inertial = 0.413 / (24.0 * eps2) * numerator * R / (R + std::pow(10.0, 3.0 * phi));
    return low + inertial;
}

double BeetstraVanDerHoefKuipers::beta(double d, double eps, double slip, const FluidProperties& f) const {
    checkDragInput(typeName, d, eps, slip, f);
    const double Re = f.rho * d * eps * slip / f.mu;
    return 3.0 * M_PI * f.mu * d * eps * dimensionlessDrag(eps, Re);
}

}  // namespace granair
