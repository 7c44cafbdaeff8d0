// TagCellHints.hpp: the cell each of this rank's own particles was found in
// at the last forward(), looked up by the particle's atom tag.
//
// The exchange's first hint for a particle is its own cell of the last
// coupling step (a particle moves less than a cell per step, so the face-plane
// test of that cell nearly always hits). Keyed by list position alone, the
// hint goes wrong for every particle after LIGGGHTS re-sorts its atoms
// (`atom_modify sort`, every 1000 steps by default): each then failed the
// test of a stranger's cell and its 6 neighbours before the next hint was
// tried. Here the position is checked against the tag (no re-sort since: the
// same tag at the same position, one compare); where it differs, at the
// position shifted by the offset of the last particle found elsewhere and a
// few around it (LIGGGHTS sorts its atoms by spatial bin at every full setup,
// i.e. every coupling step in which the sink deleted some: a particle that
// changed bin shifts the ones between by one place, so along the list the
// offset changes slowly: the wedge-silo demo finds 60 % of its particles
// elsewhere every step); failing that, the tag is looked up in the last
// step's tags, sorted once per forward() on the first such miss (binary
// search). Cost: 12 bytes per own particle (the last step's
// tags and cells, the sorted index, built only after a re-sort; tags are
// LIGGGHTS 3.8's int); the cells found this step are the caller's.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/CapacityBytes.hpp"

namespace granair {

class TagCellHints {
public:
    // Start a forward(): the cells found in the last one (`cells`, in the
    // order their tags were given to note()) become the hints; `cells`
    // receives the storage of the hints before them (contents unspecified),
    // for the caller to refill.
    void beginStep(std::vector<int>& cells);

    // The cell the particle with tag `id`, now at position j of this step's
    // list, was found in at the last step; -1 if it was not there.
    int lastCell(std::size_t j, std::int64_t id);

    // End a forward(): this step's tags, tagOf(j) for j = 0 .. n-1, replace
    // the last step's (after every lastCell() call of the step: the lookups
    // read the old ones in place, so no second tag list is kept).
    template <class TagOf>
    void endStep(std::size_t n, const TagOf& tagOf) {
        reserveGrowing(lastIds_, n);  // by an eighth, not doubled, as a rank's particles grow
        lastIds_.resize(n);
        for (std::size_t j = 0; j < n; ++j) lastIds_[j] = key(tagOf(j));
        sorted_ = false;
    }

    // Particles of the last step found at another position (a re-sort),
    // since the last beginStep().
    std::int64_t sortedLookups() const { return sortedLookups_; }
    // Of those, the ones the shifted positions missed (binary searches).
    std::int64_t tagSearches() const { return tagSearches_; }

    std::size_t bufferBytes() const;

private:
    static std::int32_t key(std::int64_t id);
    // The key of the tag at position pos of lastIds_, plus one: -1 sorts first, unsigned.
    std::uint32_t ukey(std::int32_t pos) const {
        return static_cast<std::uint32_t>(lastIds_[static_cast<std::size_t>(pos)]) + 1u;
    }
    // Positions [first, last) of lastIds_ into ascending tag order.
    void sortByTag(std::int32_t* first, std::int32_t* last) const;
    void radixPass(std::int32_t* first, std::int32_t* last, int shift) const;
    std::vector<std::int32_t> lastIds_;
    std::vector<int> lastCells_;
    std::vector<std::int32_t> byId_;  // positions in lastIds_, ascending tag
    bool sorted_ = false;
    std::ptrdiff_t shift_ = 0;  // position offset of the last particle found elsewhere
    std::int64_t sortedLookups_ = 0, tagSearches_ = 0;
};

}  // namespace granair
