// CellLocator.hpp: the particle-to-cell mapping interface.
//
// One object per rank describing the rank's LOCAL part of the CFD mesh.
// cfd-side implements it on the OpenFOAM mesh; coupling/mapping/BoxMesh is a
// structured-box implementation used by the coupling library's own tests.
// Cell indices are local to the rank: 0 .. nCells()-1.
#pragma once
#include <vector>

#include "core/Vec3.hpp"

namespace granair {

class CellLocator {
public:
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
};

}  // namespace granair
