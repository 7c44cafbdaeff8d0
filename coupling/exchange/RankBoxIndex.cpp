// RankBoxIndex.cpp: see RankBoxIndex.hpp.
#include "exchange/RankBoxIndex.hpp"

#include <algorithm>
#include <cmath>

namespace granair {

namespace {
// Up to this many non-empty boxes a linear scan beats the grid.
constexpr int kLinearScanMax = 8;
// At most this many bins per axis (bounds the grid memory at 64^3 bins).
constexpr int kMaxBinsPerAxis = 64;
}  // namespace

void RankBoxIndex::build(const std::vector<Box>& boxes) {
    boxes_ = boxes;
    nonEmpty_.clear();
    union_ = Box{};
    for (int r = 0; r < static_cast<int>(boxes.size()); ++r)
        if (!boxes[r].empty()) {
            nonEmpty_.push_back(r);
            union_.expand(boxes[r].lo);
            union_.expand(boxes[r].hi);
        }
    binStart_.clear();
    binRanks_.clear();
    if (static_cast<int>(nonEmpty_.size()) <= kLinearScanMax) return;

    // About 2 bins per box per axis: a bin then meets only a few boxes for
    // any layout of roughly equal subdomains.
    const int perAxis =
        std::clamp(static_cast<int>(std::lround(2 * std::cbrt(nonEmpty_.size()))), 1, kMaxBinsPerAxis);
    for (int a = 0; a < 3; ++a) {
        const double extent = union_.hi[a] - union_.lo[a];
        bins_[a] = extent > 0 ? perAxis : 1;
        binSize_[a] = extent > 0 ? extent / bins_[a] : 1.0;
    }
    const int total = bins_[0] * bins_[1] * bins_[2];
    // Two passes over the boxes: count per bin, then fill (CSR).
    binStart_.assign(total + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<int> cursor;
        if (pass == 1) {
            for (int b = 0; b < total; ++b) binStart_[b + 1] += binStart_[b];
            binRanks_.resize(binStart_[total]);
            cursor.assign(binStart_.begin(), binStart_.end() - 1);
        }
        for (int r : nonEmpty_) {
            int lo[3], hi[3];
            for (int a = 0; a < 3; ++a) {
                lo[a] = binOf(a, boxes_[r].lo[a]);
                hi[a] = binOf(a, boxes_[r].hi[a]);
            }
            for (int k = lo[2]; k <= hi[2]; ++k)
                for (int j = lo[1]; j <= hi[1]; ++j)
                    for (int i = lo[0]; i <= hi[0]; ++i) {
                        const int b = i + bins_[0] * (j + bins_[1] * k);
                        if (pass == 0)
                            ++binStart_[b + 1];
                        else
                            binRanks_[cursor[b]++] = r;  // ranks ascending: nonEmpty_ is
                    }
        }
    }
}

int RankBoxIndex::binOf(int axis, double coordinate) const {
    const double s = std::floor((coordinate - union_.lo[axis]) / binSize_[axis]);
    if (!(s >= 0)) return 0;
    return s >= bins_[axis] ? bins_[axis] - 1 : static_cast<int>(s);
}

void RankBoxIndex::find(const Vec3& x, std::vector<int>& out) const {
    out.clear();
    if (!union_.contains(x)) return;  // also rejects NaN
    if (binStart_.empty()) {
        for (int r : nonEmpty_)
            if (boxes_[r].contains(x)) out.push_back(r);
        return;
    }
    const int b = binOf(0, x[0]) + bins_[0] * (binOf(1, x[1]) + bins_[1] * binOf(2, x[2]));
    for (int p = binStart_[b]; p < binStart_[b + 1]; ++p)
        if (boxes_[binRanks_[p]].contains(x)) out.push_back(binRanks_[p]);
}

}  // namespace granair
