// CgKernel.cpp: see CgKernel.hpp.
#include "cg/CgKernel.hpp"

#include <cmath>

#include "cg/GaussLegendre.hpp"
#include "core/Error.hpp"

namespace granair {

namespace {

// Surface of the unit sphere in D dimensions (S_1 = 2 counts both ends).
double unitSphere(int d) { return d == 1 ? 2.0 : d == 2 ? 2.0 * M_PI : 4.0 * M_PI; }

// S_D int_0^c rho^(D - 1 + extra) f(rho) drho by 64-point Gauss-Legendre:
// exact for the polynomial shapes, to round-off for the truncated Gaussian.
double radialMoment(const CgKernelShape& s, int d, int extra) {
    const auto& gl = gaussLegendre(64);
    const double c = s.cutoff();
    double sum = 0.0;
    for (std::size_t k = 0; k < gl.x.size(); ++k) {
        const double rho = 0.5 * c * (gl.x[k] + 1.0);
        sum += gl.w[k] * std::pow(rho, d - 1 + extra) * s.shape(rho * rho);
    }
    return unitSphere(d) * 0.5 * c * sum;
}

}  // namespace

double shortInterval(const CgKernelShape& s, double p2, double a0, double a1) {
    const auto& gl = gaussLegendre(4);
    const double m = 0.5 * (a0 + a1), h = 0.5 * (a1 - a0);
    double sum = 0.0;
    for (int q = 0; q < 4; ++q) {
        const double a = m + h * gl.x[q];
        sum += gl.w[q] * s.shape(p2 + a * a);
    }
    return h * sum;
}

CgKernel::CgKernel(std::shared_ptr<const CgKernelShape> shape, int dims)
    : shape_(std::move(shape)), dims_(dims) {
    if (dims_ < 0 || dims_ > 3) fail("CgKernel: ", dims_, " resolved dimensions (expected 0..3)");
    if (dims_ == 0) return;
    if (!shape_) fail("CgKernel: no shape");
    const double n0 = radialMoment(*shape_, dims_, 0);
    norm_ = 1.0 / n0;
    sigma_ = std::sqrt(radialMoment(*shape_, dims_, 2) * norm_ / dims_);
}

CgKernel CgKernel::withStandardDeviation(const CgKernelShape& shape, int dims, double sigma) {
    if (!(sigma > 0.0) || !std::isfinite(sigma))
        fail<InputError>("kernel standard deviation ", sigma, " m: expected a finite value > 0");
    if (dims == 0) return CgKernel(shape.scaled(1.0), 0);
    const CgKernel unit(shape.scaled(1.0), dims);
    return CgKernel(shape.scaled(sigma / unit.standardDeviation()), dims);
}

}  // namespace granair
