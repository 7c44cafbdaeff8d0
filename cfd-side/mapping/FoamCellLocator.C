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
    mesh_(mesh),
    cells_(mesh.cells()),
    cellCells_(mesh.cellCells()),
    owner_(mesh.faceOwner()),
    faceCentres_(mesh.faceCentres()),
    faceAreas_(mesh.faceAreas())
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
}

inline bool FoamCellLocator::inCell(const point& x, label celli) const
{
    // primitiveMesh::pointInCell: outside if (n & (x - c_f)) > 0 for a face
    // normal n pointing out of the cell (the owner's area vector, negated
    // for a neighbour); -(a & b) is exactly (-a) & b, hence d < 0 there.
    for (const label facei : cells_[celli])
    {
        const vector proj = x - faceCentres_[facei];
        const scalar d = faceAreas_[facei] & proj;
        if (owner_[facei] == celli ? d > 0 : d < 0)
        {
            return false;
        }
    }
    return true;
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
    if (inCell(p, hint))
    {
        return hint;
    }
    for (const label nb : cellCells_[hint])
    {
        if (inCell(p, nb))
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

const ::granair::CellArrays& FoamCellLocator::cellArrays() const
{
    static_assert(sizeof(vector) == 3*sizeof(double), "cell centres are read as 3 doubles each");
    if (!arrays_.neighbourStart)
    {
        const labelListList& cc = cellCells_;
        neighbourStart_.assign(1, 0);
        neighbourStart_.reserve(std::size_t(mesh_.nCells()) + 1);
        std::size_t n = 0;
        for (const labelList& nb : cc)
        {
            n += std::size_t(nb.size());
        }
        neighbours_.reserve(n);
        for (const labelList& nb : cc)
        {
            neighbours_.insert(neighbours_.end(), nb.begin(), nb.end());
            neighbourStart_.push_back(int(neighbours_.size()));
        }
        arrays_.centres = reinterpret_cast<const double*>(mesh_.C().primitiveField().cdata());
        arrays_.volumes = mesh_.V().cdata();
        arrays_.neighbours = neighbours_.data();
        arrays_.neighbourStart = neighbourStart_.data();
    }
    return arrays_;
}

std::size_t FoamCellLocator::cellArrayBytes() const
{
    return (neighbourStart_.capacity() + neighbours_.capacity())*sizeof(int);
}

} // namespace granair
} // namespace Foam
