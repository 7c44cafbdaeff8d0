// GaussKernel.hpp: the truncated Gaussian CG kernel ("gauss").
//
// Shape: f(rho) = exp(-rho^2 / (2 w^2)) for rho < c = cutoff * w, 0 beyond;
// normalised over the truncated ball of the resolved dimensions (CgKernel),
// e.g. in 3-D N_3 = (2 pi)^(3/2) w^3 [erf(k/sqrt 2) - sqrt(2/pi) k exp(-k^2/2)]
// with k = c/w, so the integral is 1 exactly, not 1 - O(exp(-k^2/2)).
// Line integral (exact): for h^2 = c^2 - p2 > 0 and [a0, a1] clipped to [-h, h],
//     exp(-p2/(2 w^2)) sqrt(pi/2) w [erf(a1/(sqrt 2 w)) - erf(a0/(sqrt 2 w))].
// Standard deviation per axis: w for a large cutoff; at k = 3 the truncation
// narrows it to 0.9580 w in 3-D, 0.9744 w in 2-D, 0.9866 w in 1-D (CgKernel
// computes it; MercuryCG's setStandardDeviation uses the untruncated w).
//
// Parameters: width w [m] > 0 (required); cutoff k = c/w in widths,
// 1 <= k <= 10, default 3 (MercuryCG's default).
//
// References: Weinhart, T., Thornton, A.R., Luding, S., Bokhove, O. (2012).
// From discrete particles to continuum fields near a boundary. Granular
// Matter 14:289-294. Goldhirsch, I. (2010). Stress, stress asymmetry and
// couple stress: from discrete particles to continuous fields. Granular
// Matter 12:239-252.
#pragma once
#include "cg/CgKernel.hpp"

namespace granair {

class GaussKernel : public CgKernelShape {
public:
    static constexpr const char* typeName = "gauss";
    static constexpr double defaultCutoff = 3.0;

    GaussKernel(double width, double cutoffInWidths = defaultCutoff);
    static std::unique_ptr<CgKernelShape> fromDict(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double width() const override { return w_; }
    double cutoff() const override { return c_; }
    double shape(double rho2) const override;
    double shapeLineIntegral(double p2, double a0, double a1) const override;
    std::unique_ptr<CgKernelShape> scaled(double factor) const override;

private:
    double w_, k_, c_, inv2w2_;
};

}  // namespace granair
