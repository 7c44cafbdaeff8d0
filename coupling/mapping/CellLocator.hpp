// CellLocator.hpp: the particle-to-cell mapping interface.
//
// One object per rank describing the rank's LOCAL part of the CFD mesh.
// cfd-side implements it on the OpenFOAM mesh; coupling/mapping/BoxMesh is a
// structured-box implementation used by the coupling library's own tests.
// Cell indices are local to the rank: 0 .. nCells()-1.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "core/Vec3.hpp"

namespace granair {

// The cells as flat arrays, for loops that visit many cells per particle
// (the gaussian stencil's breadth-first search): one virtual call per mesh
// instead of three per visited cell. Pointers stay valid while the locator
// lives and its mesh does not change.
struct CellArrays {
    const double* centres = nullptr;       // 3 per cell [m]
    const double* volumes = nullptr;       // 1 per cell [m3]
    const int* neighbourStart = nullptr;   // nCells + 1: cell c's face neighbours are
    const int* neighbours = nullptr;       //   neighbours[neighbourStart[c] .. neighbourStart[c+1])
};

class CellLocator {
public:
    CellLocator() = default;
    CellLocator(const CellLocator&) = default;
    CellLocator& operator=(const CellLocator&) = default;
    virtual ~CellLocator() = default;

    virtual int nCells() const = 0;
    // Local cell containing x, or -1 when x is not in this rank's part of the
    // mesh. `hint` is a cell near x (e.g. last step's cell) or -1.
    virtual int findCell(const Vec3& x, int hint = -1) const = 0;
    // Cheap test: `hint` or one of its face neighbours if it holds x, else
    // -1 (no global search). Lets a caller try a second hint before paying
    // for findCell's global search. Where that search is cheap anyway (a
    // structured box) the default simply calls findCell.
    virtual int findCellNear(const Vec3& x, int hint) const { return findCell(x, hint); }
    virtual double cellVolume(int cell) const = 0;
    virtual Vec3 cellCentre(int cell) const = 0;
    // Local face neighbours of a cell (cells across processor boundaries are
    // not included).
    virtual void cellNeighbours(int cell, std::vector<int>& out) const = 0;
    // Bounding box of this rank's cells.
    virtual Box bounds() const = 0;

    // The same cells as flat arrays (same values, same neighbour order as
    // cellCentre / cellVolume / cellNeighbours). The default copies them from
    // the calls above on first use (28 + 32 bytes per cell plus 4 per face
    // neighbour); a locator that holds them already (cfd-side: OpenFOAM's
    // cell centres and volumes) overrides it and points at its own storage.
    virtual const CellArrays& cellArrays() const;
    // Bytes this locator holds for cellArrays() (for the memory report).
    virtual std::size_t cellArrayBytes() const;

private:
    // The default cellArrays()'s copy, built on first use. A copy of the
    // locator starts without one (it may describe other cells).
    struct ArrayCopy {
        std::vector<double> centres, volumes;
        std::vector<int> start, neighbours;
        CellArrays view;
    };
    struct ArrayCache {
        ArrayCache() = default;
        ArrayCache(const ArrayCache&) {}
        ArrayCache& operator=(const ArrayCache&) {
            copy.reset();
            return *this;
        }
        std::unique_ptr<ArrayCopy> copy;
    };
    mutable ArrayCache cache_;
};

}  // namespace granair
