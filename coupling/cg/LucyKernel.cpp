// LucyKernel.cpp: see LucyKernel.hpp.
#include "cg/LucyKernel.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace granair {

LucyKernel::LucyKernel(double radius) : c_(radius) {
    if (!(c_ > 0.0) || !std::isfinite(c_)) fail<InputError>("lucy kernel: width ", c_, " m, expected > 0");
}

std::unique_ptr<CgKernelShape> LucyKernel::fromDict(const Dictionary& dict) {
    const double c = dict.getDouble("width", 0.0, 1e300);
    if (!(c > 0.0)) fail<InputError>(dict.where("width"), ": expected a kernel width (cutoff radius) > 0 [m]");
    return std::make_unique<LucyKernel>(c);
}

double LucyKernel::shape(double rho2) const {
    if (rho2 >= c_ * c_) return 0.0;
    const double q = std::sqrt(rho2) / c_;
    const double m = 1.0 - q;
    return (1.0 + 3.0 * q) * m * m * m;
}

double LucyKernel::antiderivative(double p2, double a) const {
    const double a2 = a * a;
    const double s = std::sqrt(a2 + p2);
    // int (p2 + a^2)^(3/2) da; the asinh term vanishes with p2.
    double g = a * (2.0 * a2 + 5.0 * p2) * s / 8.0;
    if (p2 > 0.0) g += 3.0 * p2 * p2 * std::asinh(a / std::sqrt(p2)) / 8.0;
    const double c2 = c_ * c_;
    return a - 6.0 * (p2 * a + a2 * a / 3.0) / c2 + 8.0 * g / (c2 * c_) -
           3.0 * (p2 * p2 * a + 2.0 * p2 * a2 * a / 3.0 + a2 * a2 * a / 5.0) / (c2 * c2);
}

double LucyKernel::shapeLineIntegral(double p2, double a0, double a1) const {
    if (!clipToSupport(c_, p2, a0, a1)) return 0.0;
    if (a1 - a0 < 1e-3 * c_) {
        // Short interval: Gauss-Legendre, split at a = 0 (the |x|^3 term),
        // where the antiderivative difference would lose digits.
        if (a0 < 0.0 && a1 > 0.0) return shortInterval(*this, p2, a0, 0.0) + shortInterval(*this, p2, 0.0, a1);
        return shortInterval(*this, p2, a0, a1);
    }
    return antiderivative(p2, a1) - antiderivative(p2, a0);
}

std::unique_ptr<CgKernelShape> LucyKernel::scaled(double factor) const {
    return std::make_unique<LucyKernel>(c_ * factor);
}

}  // namespace granair
