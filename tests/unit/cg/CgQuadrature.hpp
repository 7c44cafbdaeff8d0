// CgQuadrature.hpp: accurate nested quadrature for the CG tests.
//
// The CG fields are smooth inside each kernel's support but not across its
// edge (a jump for the truncated Gaussian and the ball, a sqrt-type edge of
// the integrated inner dimensions). Integrating them to ~1e-12 therefore
// splits every level at the support edges the test knows ("breaks") and
// maps each piece [a, b] by x = a + (b - a)(1 - cos t)/2 onto t in [0, pi],
// which smooths square-root end behaviour, then uses Gauss-Legendre in t.
// The nodes of all levels are generated first and the fields evaluated in
// one call (CoarseGrainer::evaluateAt).
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "cg/GaussLegendre.hpp"

namespace granair::cgtest {

struct Node {
    double u[3] = {0, 0, 0};
    double w = 1.0;
};

// breaks(level, u): sorted or unsorted break points of level `level` given the
// outer coordinates u[0..level-1]; the first and last are the integration limits.
using Breaks = std::function<std::vector<double>(int level, const double* u)>;

inline void addLevel(int level, int dims, const Breaks& breaks, int n, Node node, std::vector<Node>& out) {
    if (level >= dims || level >= 3) {
        out.push_back(node);
        return;
    }
    std::vector<double> b = breaks(level, node.u);
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end(), [](double x, double y) { return std::abs(x - y) < 1e-300; }),
            b.end());
    const auto& gl = gaussLegendre(n);
    for (std::size_t p = 0; p + 1 < b.size(); ++p) {
        const double a = b[p], c = b[p + 1];
        if (!(c > a)) continue;
        for (int q = 0; q < n; ++q) {
            const double t = 0.5 * M_PI * (gl.x[q] + 1.0);
            Node m = node;
            m.u[level] = a + 0.5 * (c - a) * (1.0 - std::cos(t));
            m.w = node.w * gl.w[q] * 0.5 * M_PI * 0.5 * (c - a) * std::sin(t);
            addLevel(level + 1, dims, breaks, n, m, out);
        }
    }
}

inline std::vector<Node> nestedRule(int dims, const Breaks& breaks, int n) {
    std::vector<Node> out;
    if (dims == 0) {
        out.push_back(Node{});
        return out;
    }
    addLevel(0, dims, breaks, n, Node{}, out);
    return out;
}

// Breaks graded geometrically towards x1 from x0 (x0 < x1 or x0 > x1): for
// a piece that ends at a distance d from a singularity much closer than its
// length, pieces of length d, 2d, 4d, ... keep Gauss-Legendre exponential.
inline void addGraded(std::vector<double>& b, double x0, double x1, double d) {
    const double L = std::abs(x1 - x0), s = x1 > x0 ? 1.0 : -1.0;
    for (double t = d; t < L; t *= 2.0) b.push_back(x1 - s * t);
}

// Half-chord of a ball of radius c at squared offset d2 from its centre (0 outside).
inline double chord(double c, double d2) { return d2 < c * c ? std::sqrt(c * c - d2) : 0.0; }

}  // namespace granair::cgtest
