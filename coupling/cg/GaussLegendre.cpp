// GaussLegendre.cpp: see GaussLegendre.hpp.
#include "cg/GaussLegendre.hpp"

#include <cmath>
#include <array>
#include <mutex>

#include "core/Error.hpp"

namespace granair {

namespace {

// P_n(x) and P_n'(x) by the three-term recurrence.
void legendre(int n, double x, double& p, double& dp) {
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    p = p1;
    dp = n * (x * p1 - p0) / (x * x - 1.0);
}

GaussLegendreRule computeRule(int n) {
    GaussLegendreRule r;
    r.x.resize(n);
    r.w.resize(n);
    for (int i = 0; i < (n + 1) / 2; ++i) {
        // Tricomi's initial guess for the i-th root from the top, then Newton.
        double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), p = 0.0, dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            legendre(n, x, p, dp);
            const double dx = p / dp;
            x -= dx;
            if (std::abs(dx) < 1e-17) break;
        }
        legendre(n, x, p, dp);  // the derivative at the converged root, for the weight
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        r.x[n - 1 - i] = x;
        r.x[i] = -x;
        r.w[i] = r.w[n - 1 - i] = w;
    }
    if (n % 2 == 1) r.x[n / 2] = 0.0;
    return r;
}

}  // namespace

const GaussLegendreRule& gaussLegendre(int n) {
    if (n < 1 || n > 200) fail("gaussLegendre: order ", n, " outside 1..200");
    // One rule per order, computed on first use; call_once is an atomic load
    // afterwards (the rules are fetched in the snapshot loop).
    static std::array<std::once_flag, 201> once;
    static std::array<GaussLegendreRule, 201> rules;
    std::call_once(once[n], [n] { rules[n] = computeRule(n); });
    return rules[n];
}

}  // namespace granair
