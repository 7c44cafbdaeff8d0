// CellLocator::cellArrays(): the flat arrays hold exactly what the virtual
// calls return (centres, volumes, face neighbours in the same order), on a
// whole box and on a slab of it; a copied locator builds its own.
#include <catch2/catch.hpp>

#include "mapping/BoxMesh.hpp"

using namespace granair;

namespace {
void checkArrays(const CellLocator& m) {
    const CellArrays& a = m.cellArrays();
    REQUIRE(a.centres);
    REQUIRE(a.volumes);
    REQUIRE(a.neighbourStart);
    CHECK(a.neighbourStart[0] == 0);
    std::vector<int> nb;
    for (int c = 0; c < m.nCells(); ++c) {
        const Vec3 x = m.cellCentre(c);
        for (int k = 0; k < 3; ++k) CHECK(a.centres[3 * c + k] == x[k]);
        CHECK(a.volumes[c] == m.cellVolume(c));
        m.cellNeighbours(c, nb);
        REQUIRE(a.neighbourStart[c + 1] - a.neighbourStart[c] == static_cast<int>(nb.size()));
        for (std::size_t j = 0; j < nb.size(); ++j) CHECK(a.neighbours[a.neighbourStart[c] + j] == nb[j]);
    }
    CHECK(&m.cellArrays() == &a);  // built once
    CHECK(m.cellArrayBytes() > 0);
}
}  // namespace

TEST_CASE("cell arrays equal the locator's calls", "[mapping]") {
    const BoxMesh whole(Vec3(0, 0, 0), Vec3(1, 2, 3), {3, 4, 5});
    checkArrays(whole);
    const BoxMesh slab = BoxMesh::slab(Vec3(0, 0, 0), Vec3(1, 2, 3), {3, 4, 5}, 2, 1, 2);
    checkArrays(slab);
    const BoxMesh copy = slab;  // starts without arrays, builds its own
    CHECK(copy.cellArrayBytes() == 0);
    checkArrays(copy);
    CHECK(copy.cellArrays().centres != slab.cellArrays().centres);
}
