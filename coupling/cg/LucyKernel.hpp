// LucyKernel.hpp: Lucy's polynomial CG kernel ("lucy").
//
// Shape: f(q) = (1 + 3q)(1 - q)^3 = 1 - 6q^2 + 8q^3 - 3q^4, q = rho/c < 1;
// zero with its first two derivatives at q = 1, so fields are twice
// differentiable. Normalisation 5/(4c), 5/(pi c^2), 105/(16 pi c^3) in
// 1, 2, 3-D (computed by CgKernel). Line integral (exact): with
// s = sqrt(a^2 + p2), the antiderivative of f(s/c) in a is
//     a - 6 (p2 a + a^3/3)/c^2 - 3 (p2^2 a + 2 p2 a^3/3 + a^5/5)/c^4
//       + 8 [a (2a^2 + 5 p2) s/8 + 3 p2^2 asinh(a/sqrt p2)/8]/c^3.
// Standard deviation per axis c/sqrt(12) = 0.2887 c in 3-D, 0.2988 c in 2-D,
// 0.3086 c in 1-D (CgKernel computes it).
//
// Parameters: width = the cutoff radius c [m] > 0 (required), as MercuryCG.
//
// References: Lucy, L.B. (1977). A numerical approach to the testing of the
// fission hypothesis. Astron. J. 82:1013-1024. Weinhart, T., Hartkamp, R.,
// Thornton, A.R., Luding, S. (2013). Coarse-grained local and objective
// continuum description of three-dimensional granular flows down an
// inclined surface. Phys. Fluids 25:070605.
#pragma once
#include "cg/CgKernel.hpp"

namespace granair {

class LucyKernel : public CgKernelShape {
public:
    static constexpr const char* typeName = "lucy";

    explicit LucyKernel(double radius);
    static std::unique_ptr<CgKernelShape> fromDict(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double width() const override { return c_; }
    double cutoff() const override { return c_; }
    double shape(double rho2) const override;
    double shapeLineIntegral(double p2, double a0, double a1) const override;
    std::unique_ptr<CgKernelShape> scaled(double factor) const override;

private:
    double antiderivative(double p2, double a) const;
    double c_;
};

}  // namespace granair
