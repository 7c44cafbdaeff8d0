// GaussianVoidFraction.cpp: see GaussianVoidFraction.hpp.
#include "voidfraction/GaussianVoidFraction.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace granair {

GaussianVoidFraction::GaussianVoidFraction(double width, double cutoff) : width_(width), cutoff_(cutoff) {
    if (!(width > 0) || !std::isfinite(width))
        failParameter("width", "gaussian void fraction: width = ", width, " [m], expected a finite width > 0");
    if (!(cutoff >= minCutoff && cutoff <= maxCutoff))
        failParameter("cutoff", "gaussian void fraction: cutoff = ", cutoff, ", expected ", minCutoff,
                      " <= cutoff <= ", maxCutoff, " (in widths)");
}

std::unique_ptr<VoidFractionModel> GaussianVoidFraction::fromDictionary(const Dictionary& dict) {
    // getDouble rejects missing, non-numeric, NaN and inf; the constructor the range.
    return std::make_unique<GaussianVoidFraction>(dict.getDouble("width"), dict.getDouble("cutoff", defaultCutoff));
}

void GaussianVoidFraction::stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                                   std::vector<CellWeight>& out) const {
    const std::size_t nCells = static_cast<std::size_t>(mesh.nCells());
    if (stamp_.size() < nCells) stamp_.resize(nCells, 0);  // grows once per mesh, not per particle
    if (++generation_ == 0) {                              // wrapped after 2^32 particles: clear old stamps
        std::fill(stamp_.begin(), stamp_.end(), 0u);
        generation_ = 1;
    }
    const double rc2 = (cutoff_ * width_) * (cutoff_ * width_);
    // Flat arrays: the search visits ~(2 cutoff width / cell size)^3 cells per
    // particle, three virtual calls and a neighbour-list copy each otherwise.
    const CellArrays& a = mesh.cellArrays();
    const auto squaredDistance = [&](int c) {
        return (Eigen::Map<const Vec3>(a.centres + 3 * static_cast<std::size_t>(c)) - p.x).squaredNorm();
    };

    // Pass 1, breadth-first search: collect cells and their squared distance
    // (kept in out[].weight for now). `out` is the search's queue too (every
    // cell used is expanded, in the order it was found).
    out.clear();
    stamp_[static_cast<std::size_t>(centreCell)] = generation_;
    double d2min = squaredDistance(centreCell);
    out.push_back({centreCell, d2min});
    for (std::size_t head = 0; head < out.size(); ++head) {
        const int c = out[head].cell;  // a copy: push_back below may move out
        for (int k = a.neighbourStart[c]; k < a.neighbourStart[c + 1]; ++k) {
            const int nb = a.neighbours[k];
            std::uint32_t& s = stamp_[static_cast<std::size_t>(nb)];
            if (s == generation_) continue;
            s = generation_;
            const double d2 = squaredDistance(nb);
            if (d2 > rc2) continue;  // beyond the cutoff: not used, not expanded
            out.push_back({nb, d2});
            d2min = std::min(d2min, d2);
        }
    }

    // Pass 2: kernel times cell volume, relative to the nearest centre (so the
    // largest g is 1 and the sum can never underflow to 0), then normalise.
    const double k = 1.0 / (2.0 * width_ * width_);
    double sum = 0;
    for (CellWeight& cw : out) {
        cw.weight = std::exp(-(cw.weight - d2min) * k) * a.volumes[cw.cell];
        sum += cw.weight;
    }
    for (CellWeight& cw : out) cw.weight /= sum;
}

}  // namespace granair
