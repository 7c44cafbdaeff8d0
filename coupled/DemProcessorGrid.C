/*---------------------------------------------------------------------------*\
    granair: DemProcessorGrid (see DemProcessorGrid.H)
\*---------------------------------------------------------------------------*/
#include "coupled/DemProcessorGrid.H"

#include "IFstream.H"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace Foam
{
namespace granair
{

namespace
{

std::string gridText(const std::array<int, 3>& g)
{
    return std::to_string(g[0]) + " x " + std::to_string(g[1]) + " x " + std::to_string(g[2]);
}

} // namespace


DemProcessorGrid::DemProcessorGrid(const Time& runTime)
{
    if (!Pstream::parRun())
    {
        return;
    }
    const fileName file = runTime.globalPath()/"system"/"decomposeParDict";
    IFstream is(file);
    if (!is.good())
    {
        return;
    }
    const dictionary dict(is);
    method_ = dict.lookupOrDefault<word>("method", word("none"));
    if (method_ != "simple" && method_ != "hierarchical")
    {
        return;
    }
    // v1912 reads `coeffs` first, then `<method>Coeffs`.
    const dictionary* coeffs = dict.findDict("coeffs");
    if (!coeffs)
    {
        coeffs = dict.findDict(method_ + "Coeffs");
    }
    if (!coeffs || !coeffs->found("n"))
    {
        return;
    }
    const Vector<label> n(coeffs->get<Vector<label>>("n"));
    if (n.x()*n.y()*n.z() != Pstream::nProcs())
    {
        return;   // decomposePar would have refused it; LIGGGHTS picks its own
    }
    n_ = {{int(n.x()), int(n.y()), int(n.z())}};
    hasGrid_ = true;
}


std::string DemProcessorGrid::command() const
{
    if (!hasGrid_)
    {
        return "";
    }
    return "processors " + std::to_string(n_[0]) + " " + std::to_string(n_[1]) + " " + std::to_string(n_[2]);
}


void DemProcessorGrid::report(const ::granair::dem::LiggghtsDriver& dem) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    const std::array<int, 3> grid = dem.processorGrid();
    const std::vector<std::int64_t> counts = dem.particlesPerRank();
    const std::int64_t total = std::accumulate(counts.begin(), counts.end(), std::int64_t(0));
    const auto most = std::max_element(counts.begin(), counts.end());
    if (!Pstream::master())
    {
        return;
    }
    Info<< "  DEM processor grid " << gridText(grid).c_str();
    if (hasGrid_)
    {
        Info<< " (decomposeParDict: " << method_.c_str() << " n (" << n_[0] << ' ' << n_[1] << ' '
            << n_[2] << "))";
    }
    else if (!method_.empty())
    {
        Info<< " (LIGGGHTS' own; decomposeParDict method " << method_.c_str() << " has no grid to match)";
    }
    Info<< nl;
    if (hasGrid_ && grid != n_)
    {
        Info<< "granairFoam: WARNING: LIGGGHTS splits its box " << gridText(grid).c_str()
            << " (a `processors` command in the DEM script?), the CFD decomposition is "
            << gridText(n_).c_str() << " (system/decomposeParDict): each rank's particles then lie "
            << "mostly in other ranks' cells and cross ranks every coupling step. Remove the "
            << "script's `processors` command (granairFoam sets the matching grid) or make them agree."
            << nl;
    }
    const double mean = double(total)/double(counts.size());
    if (total >= 100 && double(*most) > 1.5*mean)
    {
        Info<< "granairFoam: WARNING: the DEM particles are unevenly spread: rank "
            << label(most - counts.begin()) << " holds " << *most << " of " << total
            << " (LIGGGHTS splits its box evenly in space, not by particles): the busiest rank sets "
            << "the pace. A grid along the bed's long axis, or a DEM box that the particles fill, "
            << "spreads them better." << nl;
    }
}


void DemProcessorGrid::checkNeighbourBins(const ::granair::dem::LiggghtsDriver& dem)
{
    const ::granair::dem::LiggghtsDriver::NeighbourBins b = dem.neighbourBins();
    const double perParticle = b.bins/double(std::max<std::int64_t>(b.particlesThere, 1));
    if (!Pstream::master() || !(b.bins > 1e6 && perParticle > 100))
    {
        return;
    }
    char line[512];
    std::snprintf
    (
        line, sizeof line,
        "granairFoam: WARNING: LIGGGHTS' neighbour binning makes about %.2g bins (%.2g GB) for %lld "
        "particle(s) on rank %d: bins of %.3g m (%s) over the subdomain. Every re-neighbouring "
        "visits them all (one case with 1e9 bins took 318 s and 7.8 GB). Set `neigh_modify binsize "
        "<size>` in the DEM script to a size near the largest gap between particles, or shrink the "
        "DEM box to where particles go.\n",
        b.bins, 4*b.bins/1e9, static_cast<long long>(b.particlesThere), b.rank, b.binSize,
        b.userBinSize ? "neigh_modify binsize" : "half the neighbour cutoff 2 r_max + skin"
    );
    Info<< line;
}

} // namespace granair
} // namespace Foam
