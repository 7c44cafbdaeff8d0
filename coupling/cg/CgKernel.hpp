// CgKernel.hpp: the coarse-graining kernel psi of the CG fields (docs/cg-fields.md).
//
// A kernel is a radial shape f(rho) with compact support rho < c (the
// cutoff), chosen by name (Gauss, Heaviside, Lucy: see the shape headers),
// and normalised over its truncated ball in the D resolved dimensions of the
// coordinate system (D = 1, 2, 3):
//     psi(x) = f(|x|) / N_D,   N_D = S_D int_0^c rho^(D-1) f(rho) drho,
// with S_1 = 2, S_2 = 2 pi, S_3 = 4 pi, so int_{R^D} psi dV = 1 for every D
// (the Gaussian is normalised over the truncated ball, not the full space and
// not the cube). D = 0 (a window average, coordinates O) is the unit kernel.
//
// The contact stress needs the line integral of psi along a straight
// segment; a shape provides it exactly in closed form:
//     lineIntegral(p2, a0, a1) = int_a0^a1 psi(sqrt(p2 + a^2)) da,
// p2 the squared distance of the evaluation point from the segment's line
// and a the axial coordinate along the line (any D: the line lies in the
// resolved space).
//
// Widths: every shape has one length parameter, width (the Gaussian's w,
// the cutoff radius c of Heaviside and Lucy, as in MercuryCG). To compare
// kernels, set them to the same standard deviation per axis,
//     sigma^2 = (1/D) int |x|^2 psi dV,
// with CgKernel::widthForStandardDeviation.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

namespace granair {

// The unnormalised radial profile of a kernel (one class per kernel).
class CgKernelShape {
public:
    virtual ~CgKernelShape() = default;
    virtual std::string name() const = 0;
    virtual double width() const = 0;   // the shape's length parameter [m]
    virtual double cutoff() const = 0;  // support radius c [m]: f = 0 for rho >= c
    // f at squared distance rho2 (0 outside the support).
    virtual double shape(double rho2) const = 0;
    // int_a0^a1 f(sqrt(p2 + a^2)) da, exact; 0 when the interval misses the support.
    virtual double shapeLineIntegral(double p2, double a0, double a1) const = 0;
    // The same shape with every length scaled by `factor` (for a standard deviation).
    virtual std::unique_ptr<CgKernelShape> scaled(double factor) const = 0;
};

// Clip [a0, a1] to the chord [-h, h] of the support ball (radius c) at
// squared distance p2 from its centre; false when nothing is left.
inline bool clipToSupport(double c, double p2, double& a0, double& a1) {
    const double h2 = c * c - p2;
    if (h2 <= 0.0) return false;
    const double h = std::sqrt(h2);
    a0 = std::max(a0, -h);
    a1 = std::min(a1, h);
    return a1 > a0;
}

// int_a0^a1 f(sqrt(p2 + a^2)) da by 4-point Gauss-Legendre: for intervals
// short against the cutoff (error ~ (length/width)^8), where closed forms
// lose digits to cancellation.
double shortInterval(const CgKernelShape& s, double p2, double a0, double a1);

// The registry of kernel shapes: a kernel dictionary holds `type` (gauss,
// heaviside, lucy), `width` [m] and, for gauss, `cutoff` (in widths).
const Registry<CgKernelShape>& cgKernelShapes();

class CgKernel {
public:
    // shape: owned; dims: resolved dimensions 0..3 (0: unit kernel, shape unused).
    CgKernel(std::shared_ptr<const CgKernelShape> shape, int dims);

    int dims() const { return dims_; }
    const CgKernelShape& shape() const { return *shape_; }
    std::string name() const { return dims_ == 0 ? "window" : shape_->name(); }
    double cutoff() const { return dims_ == 0 ? 0.0 : shape_->cutoff(); }
    double cutoff2() const { return cutoff() * cutoff(); }
    // psi at squared distance rho2 [1/m^D].
    double value(double rho2) const { return dims_ == 0 ? 1.0 : norm_ * shape_->shape(rho2); }
    // int_a0^a1 psi(sqrt(p2 + a^2)) da [1/m^(D-1)]; for D = 0, a1 - a0.
    double lineIntegral(double p2, double a0, double a1) const {
        if (dims_ == 0) return a1 > a0 ? a1 - a0 : 0.0;
        return norm_ * shape_->shapeLineIntegral(p2, a0, a1);
    }
    // 1/N_D, and the standard deviation per axis [m] (0 for D = 0).
    double normalisation() const { return norm_; }
    double standardDeviation() const { return sigma_; }

    // The kernel of the same type whose standard deviation per axis in `dims`
    // dimensions is `sigma` (the shape's width scaled accordingly).
    static CgKernel withStandardDeviation(const CgKernelShape& shape, int dims, double sigma);

private:
    std::shared_ptr<const CgKernelShape> shape_;
    int dims_;
    double norm_ = 1.0;
    double sigma_ = 0.0;
};

}  // namespace granair
