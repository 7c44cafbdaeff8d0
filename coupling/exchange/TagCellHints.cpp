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
        reserveGrowing(byId_, lastIds_.size());
        byId_.resize(lastIds_.size());
        std::iota(byId_.begin(), byId_.end(), 0);
        sortByTag(byId_.data(), byId_.data() + byId_.size());
        sorted_ = true;
    }
    const auto it = std::lower_bound(byId_.begin(), byId_.end(), k,
                                     [this](std::int32_t pos, std::int32_t tag) { return lastIds_[pos] < tag; });
    if (it == byId_.end() || lastIds_[*it] != k) return -1;  // a new particle
    ++sortedLookups_;
    shift_ = static_cast<std::ptrdiff_t>(*it) - static_cast<std::ptrdiff_t>(j);
    return lastCells_[*it];
}

void TagCellHints::sortByTag(std::int32_t* first, std::int32_t* last) const {
    // In place, so no buffer beyond byId_ (the coupling buffers' 150 B per
    // particle budget): an MSD radix sort on the key + 1 (key -1 first, as
    // std::sort put it), 8 bits at a time from the highest one any key uses,
    // and insertion sort for short runs. It replaced std::sort with an
    // indirect compare (one sort per step after LIGGGHTS' re-sort): -4.2 %
    // of ParticleExchange::forward's instructions on the wedge-silo demo
    // (callgrind, bench/results/wedge-demo-tag-sort.md). The keys of real
    // tags are unique, so the order is the one std::sort gave.
    std::uint32_t top = 0;
    for (const std::int32_t* q = first; q != last; ++q) top = std::max(top, ukey(*q));
    int shift = 0;
    while (shift < 24 && (top >> (shift + 8)) != 0) shift += 8;
    radixPass(first, last, shift);
}

void TagCellHints::radixPass(std::int32_t* first, std::int32_t* last, int shift) const {
    constexpr std::ptrdiff_t kShortRun = 32;
    if (last - first <= kShortRun) {
        for (std::int32_t* i = first + 1; i < last; ++i) {
            const std::int32_t v = *i;
            const std::uint32_t kv = ukey(v);
            std::int32_t* j = i;
            for (; j > first && ukey(*(j - 1)) > kv; --j) *j = *(j - 1);
            *j = v;
        }
        return;
    }
    std::ptrdiff_t count[256] = {};
    for (const std::int32_t* q = first; q != last; ++q) ++count[(ukey(*q) >> shift) & 0xffu];
    std::int32_t* start[257];
    std::int32_t* next[256];
    start[0] = first;
    for (int b = 0; b < 256; ++b) start[b + 1] = start[b] + count[b];
    std::copy(start, start + 256, next);
    // American flag permutation: each bucket's slots filled by cycling the
    // misplaced entries into their buckets.
    for (int b = 0; b < 256; ++b) {
        while (next[b] < start[b + 1]) {
            std::int32_t v = *next[b];
            int d = static_cast<int>((ukey(v) >> shift) & 0xffu);
            while (d != b) {
                std::swap(v, *next[d]++);
                d = static_cast<int>((ukey(v) >> shift) & 0xffu);
            }
            *next[b]++ = v;
        }
    }
    if (shift == 0) return;
    for (int b = 0; b < 256; ++b)
        if (count[b] > 1) radixPass(start[b], start[b + 1], shift - 8);
}

std::size_t TagCellHints::bufferBytes() const {
    return capacityBytes(lastIds_) + capacityBytes(lastCells_) + capacityBytes(byId_);
}

}  // namespace granair
