// RankBoxIndex.hpp: which ranks' boxes contain a point (candidate CFD owners).
//
// Holds one axis-aligned box per rank (the rank's CFD subdomain bounds,
// already inflated by the exchange margin) and answers "which ranks' boxes
// contain x", in ascending rank order. Few boxes are scanned linearly; many
// are binned on a uniform grid over their union, so a query costs O(boxes
// per bin) instead of O(nRanks). The answer is exact either way: a box is
// listed in every bin its closed extent touches, and the bin of a point is
// computed with the same monotone floor((x - lo) / h) as the box ends, so a
// point inside a box always lands in a bin that lists it.
#pragma once
#include <vector>

#include "core/Vec3.hpp"

namespace granair {

class RankBoxIndex {
public:
    // boxes[r] = box of rank r (empty boxes never match).
    void build(const std::vector<Box>& boxes);

    // Replace `out` by the ranks whose box contains x (closed), ascending.
    // Non-finite x matches nothing.
    void find(const Vec3& x, std::vector<int>& out) const;

    int nBins() const { return static_cast<int>(binStart_.empty() ? 0 : binStart_.size() - 1); }

private:
    int binOf(int axis, double coordinate) const;

    std::vector<Box> boxes_;
    std::vector<int> nonEmpty_;  // ranks with a non-empty box, ascending (linear scan)
    // Grid (used when there are many boxes): bins_[a] per axis over union_.
    Box union_;
    int bins_[3] = {0, 0, 0};
    Vec3 binSize_{Vec3::Ones()};
    std::vector<int> binStart_;  // CSR: ranks of bin b are binRanks_[binStart_[b] .. binStart_[b+1])
    std::vector<int> binRanks_;
};

}  // namespace granair
