/*---------------------------------------------------------------------------*\
    granair: MonitorSet (see MonitorSet.H)
\*---------------------------------------------------------------------------*/
#include "monitor/MonitorSet.H"

namespace Foam
{
namespace granair
{

static std::string axisName(const ::granair::Vec3& n)
{
    const ::granair::Vec3 u = n.normalized();
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
    {
        if (std::abs(u[a] - 1.0) < 1e-12)
        {
            return axes[a];
        }
    }
    return "n";
}

MonitorSet::MonitorSet(const fvMesh& mesh, const ::granair::Dictionary& caseDict)
{
    if (!caseDict.has("monitors"))
    {
        return;
    }
    const ::granair::Dictionary& all = caseDict.subDict("monitors");
    for (const std::string& name : all.keys())
    {
        const ::granair::Dictionary& d = all.subDict(name);
        monitors_.push_back(std::make_unique<OutletMonitor>(mesh, d));
        names_.push_back(name);
        columns_.push_back({name + "_p_Pa", "Pa"});
        columns_.push_back({name + "_dpd" + axisName(d.getVec3("normal")) + "_Pa_m", "Pa/m"});
        columns_.push_back({name + "_air_kg_s", "kg/s"});
    }
}

MonitorSet::MonitorSet
(
    const fvMesh& mesh,
    const ::granair::Dictionary& caseDict,
    const fileName& dir
)
:
    MonitorSet(mesh, caseDict)
{
    if (Pstream::master())
    {
        mkDir(dir);
    }
    std::vector<::granair::Column> cols{{"t", "s"}};
    cols.insert(cols.end(), columns_.begin(), columns_.end());
    writer_ = std::make_unique<::granair::TimeSeriesWriter>(MPI_COMM_WORLD, dir/"monitors", cols);
}

void MonitorSet::values(const AirSolver& air, std::vector<double>& row) const
{
    for (const auto& m : monitors_)
    {
        const OutletValues v = m->evaluate(air.p(), air.pFace(), air.phi(), air.eps(), air.rho());
        row.push_back(v.pMean);
        row.push_back(v.dpdn);
        row.push_back(v.massFlux);
    }
}

void MonitorSet::write(scalar t, const AirSolver& air) const
{
    if (!writer_)
    {
        return;
    }
    std::vector<double> row{t};
    values(air, row);
    writer_->append(row);
}

} // namespace granair
} // namespace Foam
