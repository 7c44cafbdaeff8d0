// TagCellHints.cpp: see TagCellHints.hpp.
#include "exchange/TagCellHints.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

#include "core/CapacityBytes.hpp"

namespace granair {

namespace {
// Positions tried on either side of the shifted one before the binary search.
constexpr std::ptrdiff_t kWindow = 4;
}  // namespace

std::int32_t TagCellHints::key(std::int64_t id) {
    // LIGGGHTS 3.8 tags are int; anything else gets a key no tag has (a
    // wrong or missing hint only costs a search, never a wrong cell).
    return id >= 0 && id <= std::numeric_limits<std::int32_t>::max() ? static_cast<std::int32_t>(id) : -1;
}

void TagCellHints::beginStep(std::vector<int>& cells) {
    std::swap(lastCells_, cells);
    // A forward() that stopped part-way left tags and cells of different
    // lengths: keep the aligned part only.
    const std::size_t n = std::min(lastIds_.size(), lastCells_.size());
    lastIds_.resize(n);
    lastCells_.resize(n);
    sorted_ = false;
    shift_ = 0;
    sortedLookups_ = 0;
    tagSearches_ = 0;
}

int TagCellHints::lastCell(std::size_t j, std::int64_t id) {
    const std::int32_t k = key(id);
    if (k < 0) return -1;
    if (j < lastIds_.size() && lastIds_[j] == k) return lastCells_[j];
    if (lastIds_.empty()) return -1;
    // The shifted position and its neighbours, nearest first.
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(lastIds_.size());
    const std::ptrdiff_t guess = static_cast<std::ptrdiff_t>(j) + shift_;
    for (std::ptrdiff_t d = 0; d <= kWindow; d = d > 0 ? -d : 1 - d) {
        const std::ptrdiff_t at = guess + d;
        if (at >= 0 && at < n && lastIds_[static_cast<std::size_t>(at)] == k) {
            shift_ = at - static_cast<std::ptrdiff_t>(j);
            ++sortedLookups_;
            return lastCells_[static_cast<std::size_t>(at)];
        }
    }
    ++tagSearches_;
    if (!sorted_) {
        byId_.resize(lastIds_.size());
        std::iota(byId_.begin(), byId_.end(), 0);
        std::sort(byId_.begin(), byId_.end(),
                  [this](std::int32_t a, std::int32_t b) { return lastIds_[a] < lastIds_[b]; });
        sorted_ = true;
    }
    const auto it = std::lower_bound(byId_.begin(), byId_.end(), k,
                                     [this](std::int32_t pos, std::int32_t tag) { return lastIds_[pos] < tag; });
    if (it == byId_.end() || lastIds_[*it] != k) return -1;  // a new particle
    ++sortedLookups_;
    shift_ = static_cast<std::ptrdiff_t>(*it) - static_cast<std::ptrdiff_t>(j);
    return lastCells_[*it];
}

std::size_t TagCellHints::bufferBytes() const {
    return capacityBytes(lastIds_) + capacityBytes(lastCells_) + capacityBytes(byId_);
}

}  // namespace granair
