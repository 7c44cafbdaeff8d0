// HeavisideKernel.hpp: the ball (top-hat) CG kernel ("heaviside").
//
// Shape: f(rho) = 1 for rho < c, 0 beyond; normalised by the ball's volume
// in the resolved dimensions (2c, pi c^2, 4/3 pi c^3). Line integral: the
// length of [a0, a1] inside [-h, h], h^2 = c^2 - p2. Standard deviation per
// axis c/sqrt(D + 2). Fields jump where a particle enters the ball, so they
// are noisy in time; useful as the classical "binning" average and to check
// the others.
//
// Parameters: width = the ball radius c [m] > 0 (required), as MercuryCG's
// Heaviside "width".
//
// Reference: Weinhart, T., Thornton, A.R., Luding, S., Bokhove, O. (2012).
// From discrete particles to continuum fields near a boundary. Granular
// Matter 14:289-294.
#pragma once
#include "cg/CgKernel.hpp"

namespace granair {

class HeavisideKernel : public CgKernelShape {
public:
    static constexpr const char* typeName = "heaviside";

    explicit HeavisideKernel(double radius);
    static std::unique_ptr<CgKernelShape> fromDict(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double width() const override { return c_; }
    double cutoff() const override { return c_; }
    double shape(double rho2) const override { return rho2 < c_ * c_ ? 1.0 : 0.0; }
    double shapeLineIntegral(double p2, double a0, double a1) const override;
    std::unique_ptr<CgKernelShape> scaled(double factor) const override;

private:
    double c_;
};

}  // namespace granair
