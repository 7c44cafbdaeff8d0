// HeavisideKernel.cpp: see HeavisideKernel.hpp.
#include "cg/HeavisideKernel.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace granair {

HeavisideKernel::HeavisideKernel(double radius) : c_(radius) {
    if (!(c_ > 0.0) || !std::isfinite(c_)) fail<InputError>("heaviside kernel: width ", c_, " m, expected > 0");
}

std::unique_ptr<CgKernelShape> HeavisideKernel::fromDict(const Dictionary& dict) {
    const double c = dict.getDouble("width", 0.0, 1e300);
    if (!(c > 0.0)) fail<InputError>(dict.where("width"), ": expected a kernel width (ball radius) > 0 [m]");
    return std::make_unique<HeavisideKernel>(c);
}

double HeavisideKernel::shapeLineIntegral(double p2, double a0, double a1) const {
    if (!clipToSupport(c_, p2, a0, a1)) return 0.0;
    return a1 - a0;
}

std::unique_ptr<CgKernelShape> HeavisideKernel::scaled(double factor) const {
    return std::make_unique<HeavisideKernel>(c_ * factor);
}

}  // namespace granair
