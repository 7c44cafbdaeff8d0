// TagCellHints and the exchange's cell search after a DEM re-sort: each own
// particle's first hint is its own last cell, found by tag when the list
// order changed (issue 22: the hints keyed by list position all missed after
// a LIGGGHTS re-sort).
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>

#include "exchange/ParticleExchange.hpp"
#include "exchange/TagCellHints.hpp"
#include "mapping/BoxMesh.hpp"

using namespace granair;

namespace {

// BoxMesh whose findCellNear only looks at the hint and its face
// neighbours (as the OpenFOAM locator does) and which counts its
// whole-mesh searches.
class StrictBoxMesh : public CellLocator {
public:
    explicit StrictBoxMesh(const BoxMesh& m) : m_(m) {}
    int nCells() const override { return m_.nCells(); }
    int findCell(const Vec3& x, int hint) const override {
        const int near = findCellNear(x, hint);
        if (near >= 0) return near;
        ++globalSearches;
        return m_.findCell(x);
    }
    int findCellNear(const Vec3& x, int hint) const override {
        if (hint < 0) return -1;
        const int c = m_.findCell(x);
        if (c == hint) return c;
        m_.cellNeighbours(hint, nb_);
        return std::find(nb_.begin(), nb_.end(), c) != nb_.end() ? c : -1;
    }
    double cellVolume(int c) const override { return m_.cellVolume(c); }
    Vec3 cellCentre(int c) const override { return m_.cellCentre(c); }
    void cellNeighbours(int c, std::vector<int>& out) const override { m_.cellNeighbours(c, out); }
    Box bounds() const override { return m_.bounds(); }
    mutable long globalSearches = 0;

private:
    const BoxMesh& m_;
    mutable std::vector<int> nb_;
};

}  // namespace

TEST_CASE("TagCellHints: by position while the order holds, by tag after a re-sort", "[exchange]") {
    TagCellHints h;
    std::vector<int> cells;
    h.beginStep(cells);
    cells.assign({10, 11, 12, 13});
    h.endStep(4, [](std::size_t j) { return 100 + static_cast<std::int64_t>(j); });
    h.beginStep(cells);  // the cells above become the hints
    CHECK(h.lastCell(0, 100) == 10);
    CHECK(h.lastCell(3, 103) == 13);
    CHECK(h.sortedLookups() == 0);
    CHECK(h.lastCell(0, 102) == 12);  // moved from position 2 to 0
    CHECK(h.lastCell(1, 999) == -1);  // a new particle
    CHECK(h.lastCell(7, 101) == 11);  // beyond the last list
    CHECK(h.lastCell(0, -5) == -1);   // not a LIGGGHTS tag: no hint, no error
    CHECK(h.sortedLookups() == 2);  // the two found elsewhere
}

TEST_CASE("TagCellHints: a list shifted by a few places needs no tag search", "[exchange]") {
    // After a DEM sort by spatial bin a particle that changed bin shifts the
    // ones between by a place: the running offset finds them all.
    TagCellHints h;
    std::vector<int> cells;
    h.beginStep(cells);
    const std::size_t n = 1000;
    cells.resize(n);
    for (std::size_t j = 0; j < n; ++j) cells[j] = static_cast<int>(10 * j);
    h.endStep(n, [](std::size_t j) { return static_cast<std::int64_t>(j + 1); });
    h.beginStep(cells);
    // Now: a new particle first, so tags 1..599 one place later, 301 and 302
    // swapped among them; 600 gone, so 601..1000 in their old places.
    std::vector<std::int64_t> now{5000};
    for (std::int64_t t = 1; t <= 300; ++t) now.push_back(t);
    now.push_back(302);
    now.push_back(301);
    for (std::int64_t t = 303; t <= 1000; ++t)
        if (t != 600) now.push_back(t);
    std::size_t found = 0;
    for (std::size_t j = 0; j < now.size(); ++j) {
        const int c = h.lastCell(j, now[j]);
        if (now[j] == 5000) {
            CHECK(c == -1);
            continue;
        }
        CHECK(c == 10 * (now[j] - 1));
        ++found;
    }
    CHECK(found == n - 1);
    CHECK(h.sortedLookups() == 598);  // found elsewhere: 1..599 but 302 (in its old place) and 600
    CHECK(h.tagSearches() == 1);  // the new particle only
}

TEST_CASE("TagCellHints: a shuffled list of tags over several radix digits is found by tag", "[exchange]") {
    // The tag index is sorted in place by 8-bit digits (short runs by
    // insertion): tags spanning three digits, a random order, some gone and
    // some new, each old one must still find its own cell.
    std::mt19937_64 rng(11);
    std::vector<std::int64_t> tags;
    for (std::int64_t t = 1; tags.size() < 3000; t += 1 + static_cast<std::int64_t>(rng() % 3000)) tags.push_back(t);
    REQUIRE(tags.back() > (1 << 16));
    std::shuffle(tags.begin(), tags.end(), rng);
    TagCellHints h;
    std::vector<int> cells;
    h.beginStep(cells);
    cells.resize(tags.size());
    for (std::size_t j = 0; j < tags.size(); ++j) cells[j] = static_cast<int>(7 * j + 1);
    h.endStep(tags.size(), [&](std::size_t j) { return tags[j]; });
    std::vector<std::pair<std::int64_t, int>> expect;
    for (std::size_t j = 0; j < tags.size(); ++j) expect.emplace_back(tags[j], cells[j]);
    h.beginStep(cells);
    std::shuffle(expect.begin(), expect.end(), rng);
    expect.resize(2500);                    // 500 gone
    expect.emplace_back(tags.back() + 5, -1);  // new ones
    expect.emplace_back(0, -1);
    std::shuffle(expect.begin(), expect.end(), rng);
    std::size_t wrong = 0, inPlace = 0;  // inPlace: by chance at their old position (no lookup elsewhere)
    for (std::size_t j = 0; j < expect.size(); ++j) {
        wrong += h.lastCell(j, expect[j].first) != expect[j].second;
        inPlace += j < tags.size() && tags[j] == expect[j].first;
    }
    CHECK(wrong == 0);
    CHECK(h.sortedLookups() == static_cast<std::int64_t>(2500 - inPlace));
}

TEST_CASE("exchange cell search: a re-sorted list keeps every particle's own last cell as its hint",
          "[exchange]") {
    const BoxMesh box(Vec3(0, 0, 0), Vec3(1, 1, 1), {8, 8, 8});
    const StrictBoxMesh mesh(box);
    ParticleExchange ex(MPI_COMM_SELF, mesh);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.01, 0.99);
    std::vector<ParticleState> dem(400);
    for (std::size_t i = 0; i < dem.size(); ++i) {
        dem[i].id = 1 + static_cast<std::int64_t>(i);
        dem[i].x = Vec3(u(rng), u(rng), u(rng));
        dem[i].radius = 1e-3;
    }
    OwnedParticles owned;
    ex.forward(dem, owned);  // first step: no hints yet
    CHECK(ex.stats().hintMisses == 400);
    CHECK(ex.stats().reordered == 0);
    // A re-sort (random order: the worst case for the neighbour-record hint),
    // particles moved by much less than a cell.
    std::shuffle(dem.begin(), dem.end(), rng);
    for (auto& p : dem) p.x += Vec3(1e-3, -1e-3, 2e-3);
    const long before = mesh.globalSearches;
    ex.forward(dem, owned);
    CHECK(ex.stats().reordered > 390);
    CHECK(ex.stats().hintMisses == 0);
    CHECK(ex.stats().globalSearches == 0);
    CHECK(mesh.globalSearches == before);
    for (std::size_t k = 0; k < owned.size(); ++k) CHECK(owned.cell(k) == box.findCell(owned.state(k).x));
    // The same order again: no lookup by tag needed.
    ex.forward(dem, owned);
    CHECK(ex.stats().reordered == 0);
    CHECK(ex.stats().hintMisses == 0);
}
