/*---------------------------------------------------------------------------*\
    granair: FoamCellLocator (see FoamCellLocator.H)
\*---------------------------------------------------------------------------*/
#include "mapping/FoamCellLocator.H"

namespace Foam
{
namespace granair
{

static inline point toPoint(const ::granair::Vec3& x)
{
    return point(x.x(), x.y(), x.z());
}

FoamCellLocator::FoamCellLocator(const fvMesh& mesh)
:
    mesh_(mesh)
{
    // Collective: build the tet decomposition and the cell octree now.
    (void)mesh_.tetBasePtIs();
    if (mesh_.nCells())
    {
        (void)mesh_.cellTree();
        const boundBox bb(mesh_.points(), false);
        bounds_.lo = ::granair::Vec3(bb.min().x(), bb.min().y(), bb.min().z());
        bounds_.hi = ::granair::Vec3(bb.max().x(), bb.max().y(), bb.max().z());
    }
    (void)mesh_.cellCells();
}

int FoamCellLocator::nCells() const
{
    return mesh_.nCells();
}

int FoamCellLocator::findCellNear(const ::granair::Vec3& x, int hint) const
{
    if (hint < 0 || hint >= mesh_.nCells() || !x.allFinite())
    {
        return -1;
    }
    const point p(toPoint(x));
    // Face planes: ~6 dot products for a hex, exact for convex cells.
    if (mesh_.pointInCell(p, hint, polyMesh::FACE_PLANES))
    {
        return hint;
    }
    for (const label nb : mesh_.cellCells()[hint])
    {
        if (mesh_.pointInCell(p, nb, polyMesh::FACE_PLANES))
        {
            return nb;
        }
    }
    return -1;
}

int FoamCellLocator::findCell(const ::granair::Vec3& x, int hint) const
{
    if (!x.allFinite() || !bounds_.contains(x))
    {
        return -1;
    }
    const int near = findCellNear(x, hint);
    if (near >= 0)
    {
        return near;
    }
    return mesh_.findCell(toPoint(x), polyMesh::CELL_TETS);
}

double FoamCellLocator::cellVolume(int cell) const
{
    return mesh_.V()[cell];
}

::granair::Vec3 FoamCellLocator::cellCentre(int cell) const
{
    const point& c = mesh_.C()[cell];
    return ::granair::Vec3(c.x(), c.y(), c.z());
}

void FoamCellLocator::cellNeighbours(int cell, std::vector<int>& out) const
{
    const labelList& nb = mesh_.cellCells()[cell];
    out.assign(nb.begin(), nb.end());
}

::granair::Box FoamCellLocator::bounds() const
{
    return bounds_;
}

} // namespace granair
} // namespace Foam
