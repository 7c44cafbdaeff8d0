// GaussKernel.cpp: see GaussKernel.hpp.
#include "cg/GaussKernel.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace granair {

GaussKernel::GaussKernel(double width, double cutoffInWidths)
    : w_(width), k_(cutoffInWidths), c_(width * cutoffInWidths), inv2w2_(0.5 / (width * width)) {
    if (!(w_ > 0.0) || !std::isfinite(w_)) fail<InputError>("gauss kernel: width ", w_, " m, expected > 0");
    if (!(k_ >= 1.0 && k_ <= 10.0))
        fail<InputError>("gauss kernel: cutoff ", k_, " widths, expected 1 <= cutoff <= 10");
}

std::unique_ptr<CgKernelShape> GaussKernel::fromDict(const Dictionary& dict) {
    const double w = dict.getDouble("width", 0.0, 1e300);
    if (!(w > 0.0)) fail<InputError>(dict.where("width"), ": expected a kernel width > 0 [m]");
    const double k = dict.has("cutoff") ? dict.getDouble("cutoff", 1.0, 10.0) : defaultCutoff;
    return std::make_unique<GaussKernel>(w, k);
}

double GaussKernel::shape(double rho2) const {
    return rho2 < c_ * c_ ? std::exp(-rho2 * inv2w2_) : 0.0;
}

double GaussKernel::shapeLineIntegral(double p2, double a0, double a1) const {
    if (!clipToSupport(c_, p2, a0, a1)) return 0.0;
    if (a1 - a0 < 1e-3 * c_) {
        // A short interval (a contact nearly perpendicular to the resolved
        // directions): 4-point Gauss-Legendre, where the erf difference
        // would lose digits to cancellation.
        return shortInterval(*this, p2, a0, a1);
    }
    const double s = 1.0 / (std::sqrt(2.0) * w_);
    // erfc differences where both ends lie on one side keep full precision.
    double d;
    if (a0 >= 0.0) d = std::erfc(a0 * s) - std::erfc(a1 * s);
    else if (a1 <= 0.0) d = std::erfc(-a1 * s) - std::erfc(-a0 * s);
    else d = std::erf(a1 * s) - std::erf(a0 * s);
    return std::exp(-p2 * inv2w2_) * std::sqrt(0.5 * M_PI) * w_ * d;
}

std::unique_ptr<CgKernelShape> GaussKernel::scaled(double factor) const {
    return std::make_unique<GaussKernel>(w_ * factor, k_);
}

}  // namespace granair
