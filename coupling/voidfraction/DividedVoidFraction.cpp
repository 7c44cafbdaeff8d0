// DividedVoidFraction.cpp: see DividedVoidFraction.hpp for the point layout.
#include "voidfraction/DividedVoidFraction.hpp"

#include <array>
#include <cmath>

#include "core/Error.hpp"

namespace granair {

namespace {
constexpr int pointsPerShell = 24;

// The 24 unit directions: sign changes x cyclic permutations of (p, q, s).
std::array<Vec3, pointsPerShell> shellDirections() {
    const double r5 = 1.0 / std::sqrt(5.0);
    const double u[3] = {std::sqrt((1 - r5) / 8), std::sqrt((1 + r5) / 8), std::sqrt(0.75)};
    std::array<Vec3, pointsPerShell> d;
    int n = 0;
    for (int perm = 0; perm < 3; ++perm)
        for (int signs = 0; signs < 8; ++signs) {
            Vec3 v;
            for (int a = 0; a < 3; ++a) v[a] = ((signs >> a) & 1 ? -1.0 : 1.0) * u[(a + perm) % 3];
            d[n++] = v;
        }
    return d;
}
}  // namespace

DividedVoidFraction::DividedVoidFraction(long shells) : shells_(static_cast<int>(shells)) {
    if (shells < 1 || shells > maxShells)  // before anything uses the narrowed shells_
        failParameter("shells", "divided void fraction: shells = ", shells, ", expected 1 <= shells <= ", maxShells);
    const int n = 1 + pointsPerShell * shells_;
    const auto dirs = shellDirections();
    points_.reserve(static_cast<std::size_t>(n));
    points_.push_back(Vec3::Zero());
    for (int k = 1; k <= shells_; ++k) {
        // Shell k holds the volume fraction (1 + 24(k-1))/N .. (1 + 24k)/N.
        const double a = std::cbrt(static_cast<double>(1 + pointsPerShell * (k - 1)) / n);
        const double b = std::cbrt(static_cast<double>(1 + pointsPerShell * k) / n);
        const double rk = std::sqrt(0.6 * (std::pow(b, 5) - std::pow(a, 5)) / (b * b * b - a * a * a));
        for (const Vec3& d : dirs) points_.push_back(rk * d);
    }
}

std::unique_ptr<VoidFractionModel> DividedVoidFraction::fromDictionary(const Dictionary& dict) {
    return std::make_unique<DividedVoidFraction>(dict.getInt("shells", defaultShells));
}

void DividedVoidFraction::stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                                  std::vector<CellWeight>& out) const {
    // Count points per cell in out[].weight (small integers, exact), then divide.
    out.clear();
    out.push_back({centreCell, 1.0});  // the centre point
    const std::size_t n = points_.size();
    for (std::size_t i = 1; i < n; ++i) {
        int c = mesh.findCell(p.x + p.radius * points_[i], centreCell);
        if (c < 0) c = centreCell;  // not on this rank / outside the domain: keep the volume
        bool found = false;
        for (CellWeight& cw : out)
            if (cw.cell == c) {
                cw.weight += 1.0;
                found = true;
                break;
            }
        if (!found) out.push_back({c, 1.0});
    }
    const double nd = static_cast<double>(n);
    for (CellWeight& cw : out) cw.weight /= nd;
}

}  // namespace granair
