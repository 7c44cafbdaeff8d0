// GaussLegendre.hpp: Gauss-Legendre nodes and weights on [-1, 1].
//
// Used for the kernel normalisation and standard deviation (exact for the
// polynomial shapes, to round-off for the Gaussian) and for the azimuthal
// average of the RZ coordinates. Nodes from Newton's method on the Legendre
// polynomial (Golub-Welsch accuracy, ~1e-16), computed once per order.
#pragma once
#include <vector>

namespace granair {

struct GaussLegendreRule {
    std::vector<double> x;  // nodes in (-1, 1), ascending
    std::vector<double> w;  // weights, sum 2
};

// The n-point rule (1 <= n <= 200); cached, thread-safe after first use.
const GaussLegendreRule& gaussLegendre(int n);

}  // namespace granair
