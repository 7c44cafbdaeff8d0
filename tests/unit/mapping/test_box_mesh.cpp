// BoxMesh: cell lookup, faces and corners, decomposition into owned blocks.
#include <catch2/catch.hpp>

#include "mapping/BoxMesh.hpp"

using granair::BoxMesh;
using granair::Vec3;

TEST_CASE("box mesh finds cells, with half-open faces and the upper boundary", "[mapping]") {
    BoxMesh m(Vec3(0, 0, 0), Vec3(1, 2, 3), {2, 4, 6});
    REQUIRE(m.nCells() == 48);
    CHECK(m.cellVolume(0) == Approx(6.0 / 48).epsilon(1e-14));
    const int c = m.findCell(Vec3(0.75, 0.25, 0.1));
    CHECK(m.globalIjk(c) == BoxMesh::Index3{1, 0, 0});
    // internal face x = 0.5 belongs to the upper cell
    CHECK(m.globalIjk(m.findCell(Vec3(0.5, 0.1, 0.1)))[0] == 1);
    // the far corner belongs to the last cell
    CHECK(m.globalIjk(m.findCell(Vec3(1, 2, 3))) == BoxMesh::Index3{1, 3, 5});
    CHECK(m.findCell(Vec3(0, 0, 0)) == 0);
    CHECK(m.findCell(Vec3(1.0000001, 1, 1)) == -1);
    CHECK(m.findCell(Vec3(std::nan(""), 1, 1)) == -1);
    CHECK((m.cellCentre(c) - Vec3(0.75, 0.25, 0.25)).norm() < 1e-15);
    std::vector<int> nb;
    m.cellNeighbours(0, nb);
    CHECK(nb.size() == 3);
}

TEST_CASE("slab parts own every cell exactly once and agree on face points", "[mapping]") {
    const Vec3 lo(0, 0, 0), hi(1, 1, 1);
    const BoxMesh::Index3 n{5, 3, 7};
    for (int parts : {1, 2, 3}) {
        long total = 0;
        std::vector<BoxMesh> slabs;
        for (int p = 0; p < parts; ++p) slabs.push_back(BoxMesh::slab(lo, hi, n, parts, p, 2));
        for (const auto& s : slabs) total += s.nCells();
        CHECK(total == 5 * 3 * 7);
        // a point on a slab face is found by exactly one part
        for (double z : {0.0, 3.0 / 7, 4.0 / 7, 1.0, 0.5}) {
            int found = 0;
            for (const auto& s : slabs) found += s.findCell(Vec3(0.3, 0.3, z)) >= 0;
            CHECK(found == 1);
        }
    }
}
