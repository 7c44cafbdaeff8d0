// BoxMesh.hpp: a structured box mesh implementing CellLocator.
//
// The global box [lo, hi] is cut into n[0] x n[1] x n[2] equal cells; a rank
// owns the block of cells with global indices ownedLo <= ijk < ownedHi. Used by
// the coupling library's tests and benchmarks, and as the reference mapping
// the OpenFOAM one is checked against.
//
// Cell membership is half-open: x belongs to cell i when lo+i*h <= x < lo+(i+1)*h,
// except that x == hi belongs to the last cell. So a point on a face between
// two ranks' blocks belongs to exactly one rank.
#pragma once
#include <array>

#include "mapping/CellLocator.hpp"

namespace granair {

class BoxMesh : public CellLocator {
public:
    using Index3 = std::array<int, 3>;

    // Whole mesh on this rank.
    BoxMesh(const Vec3& lo, const Vec3& hi, const Index3& n);
    // Only the block [ownedLo, ownedHi) of cells on this rank.
    BoxMesh(const Vec3& lo, const Vec3& hi, const Index3& n, const Index3& ownedLo, const Index3& ownedHi);

    // Slab decomposition: part `part` of `nParts` equal slabs along `axis`.
    static BoxMesh slab(const Vec3& lo, const Vec3& hi, const Index3& n, int nParts, int part, int axis);

    int nCells() const override;
    int findCell(const Vec3& x, int hint = -1) const override;
    double cellVolume(int cell) const override;
    Vec3 cellCentre(int cell) const override;
    void cellNeighbours(int cell, std::vector<int>& out) const override;
    Box bounds() const override;

    // Global (i, j, k) of a local cell and back (-1 if not owned here).
    Index3 globalIjk(int cell) const;
    int localCell(const Index3& ijk) const;
    // Global linear index i + n0*(j + n1*k), the same on every rank.
    long globalIndex(int cell) const;
    const Vec3& spacing() const { return h_; }

private:
    Vec3 lo_, hi_, h_;
    Index3 n_, ownedLo_, ownedHi_, m_;  // m_ = owned block size
};

}  // namespace granair
