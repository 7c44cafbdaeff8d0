// RankBoxIndex: the candidate ranks of a point are exactly the ranks whose
// (closed) box contains it, both for the linear scan (few boxes) and the grid
// (many boxes); checked against a brute-force scan.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "exchange/RankBoxIndex.hpp"

using granair::Box;
using granair::RankBoxIndex;
using granair::Vec3;

namespace {

std::vector<int> bruteForce(const std::vector<Box>& boxes, const Vec3& x) {
    std::vector<int> out;
    for (int r = 0; r < static_cast<int>(boxes.size()); ++r)
        if (!boxes[r].empty() && boxes[r].contains(x)) out.push_back(r);
    return out;
}

// nx * ny * nz blocks tiling [0,1]^3 with shared faces, inflated by `margin`,
// plus one empty box (a rank without cells) in the middle of the list.
std::vector<Box> blockBoxes(int nx, int ny, int nz, double margin) {
    std::vector<Box> boxes;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                Box b{Vec3(double(i) / nx, double(j) / ny, double(k) / nz),
                      Vec3(double(i + 1) / nx, double(j + 1) / ny, double(k + 1) / nz)};
                boxes.push_back(b.inflated(margin));
                if (boxes.size() == 2) boxes.push_back(Box{});
            }
    return boxes;
}

// Random points in and slightly around the unit cube, plus points exactly on
// the block faces and corners (where several boxes meet).
std::vector<Vec3> probePoints(int nx, int ny, int nz) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-0.05, 1.05);
    std::vector<Vec3> pts;
    for (int n = 0; n < 4000; ++n) pts.emplace_back(u(rng), u(rng), u(rng));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) pts.emplace_back(double(i) / nx, double(j) / ny, double(k) / nz);
    return pts;
}

void checkAgainstBruteForce(int nx, int ny, int nz, double margin, bool expectGrid) {
    const auto boxes = blockBoxes(nx, ny, nz, margin);
    RankBoxIndex index;
    index.build(boxes);
    CHECK((index.nBins() > 0) == expectGrid);
    std::vector<int> got;
    std::size_t mismatches = 0, multi = 0;
    for (const Vec3& x : probePoints(nx, ny, nz)) {
        index.find(x, got);
        if (got != bruteForce(boxes, x)) ++mismatches;
        multi += got.size() > 1;
    }
    CHECK(mismatches == 0);
    CHECK(multi > 0);  // the face points did exercise several candidates
}

}  // namespace

// (One test case for the whole file: every ctest test pays an MPI start-up.)
TEST_CASE("rank box index matches brute force, NaN and far points match nothing", "[exchange]") {
    checkAgainstBruteForce(2, 2, 1, 1e-9, false);  // linear scan: 4 boxes + 1 empty
    checkAgainstBruteForce(4, 3, 5, 1e-9, true);   // grid: 60 boxes
    checkAgainstBruteForce(3, 3, 3, 0.02, true);   // grid, large margin: boxes overlap
    checkAgainstBruteForce(1, 1, 40, 0.0, true);   // grid, thin slabs: one bin on x and y

    RankBoxIndex index;
    index.build(blockBoxes(4, 4, 4, 1e-9));
    std::vector<int> got{7};
    index.find(Vec3(std::nan(""), 0.5, 0.5), got);
    CHECK(got.empty());
    index.find(Vec3(0.5, 0.5, 2.0), got);
    CHECK(got.empty());
    index.find(Vec3(0.5, INFINITY, 0.5), got);
    CHECK(got.empty());
}
