/*---------------------------------------------------------------------------*\
    granair: PowderBalance (see PowderBalance.H)
\*---------------------------------------------------------------------------*/
#include "PowderBalance.H"

#include <cmath>

#include "AirPercolation.H"
#include "core/Error.hpp"
#include "uniformDimensionedFields.H"
#include "wedgePolyPatch.H"

namespace Foam
{
namespace granair
{

namespace
{

// Full revolution / wedge volume, 1 for a non-wedge mesh. A wedge of half
// angle a whose vertices lie at (r, +-r tan a) (the axis at r = 0) holds
// 2 tan(a) int r dA of each cell's section, the revolved cell 2 pi int r dA,
// so the ratio is pi/tan(a) for every cell (cases/mcc-hopper builds its
// wedge this way).
scalar revolutionScale(const fvMesh& mesh)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp))
        {
            const scalar halfAngle = acos(min(refCast<const wedgePolyPatch>(pp).cosAngle(), scalar(1)));
            return constant::mathematical::pi/tan(halfAngle);
        }
    }
    return 1;
}

// The cells where the powder is stress-free by the boundary conditions, not
// by the numerics, which the tension_fraction leaves out: the first two cell
// layers at the outlet patch (p = 0 there) and, when the mesh continues below
// the orifice (orificeHeight given), everything below the orifice plane (the
// falling jet) and two layers above it. Layers grow by face neighbours; those
// across processor boundaries are not marked (a decomposed run counts a few
// more cells).
boolList stressFreeByConstruction
(
    const fvMesh& mesh,
    label patchi,
    scalar orificeHeight,
    const vector& up
)
{
    boolList mark(mesh.nCells(), false);
    for (const label c : mesh.boundary()[patchi].faceCells())
    {
        mark[c] = true;
    }
    if (orificeHeight < VGREAT)
    {
        forAll(mark, c)
        {
            if ((mesh.C()[c] & up) < orificeHeight) mark[c] = true;
        }
    }
    for (int layer = 1; layer < 2 + (orificeHeight < VGREAT ? 1 : 0); ++layer)
    {
        const boolList previous(mark);
        forAll(previous, c)
        {
            if (!previous[c]) continue;
            for (const label n : mesh.cellCells()[c])
            {
                mark[n] = true;
            }
        }
    }
    return mark;
}

} // namespace

PowderBalance::PowderBalance
(
    const fvMesh& mesh,
    const std::string& outletPatch,
    scalar rhoPowder,
    const volScalarField& content,
    bool withAir,
    const fileName& directory,
    scalar orificeHeight
)
:
    mesh_(mesh),
    outletPatch_(mesh.boundaryMesh().findPatchID(outletPatch)),
    rhoPowder_(rhoPowder),
    scale_(revolutionScale(mesh)),
    up_(0, 0, 1),
    air_(withAir),
    orificeHeight_(orificeHeight),
    initialMass_(0),
    discharged_(0),
    lastFlow_(0),
    steps_(0),
    unconvergedSteps_(0),
    maxOuter_(0),
    sumOuter_(0),
    lastTensionFraction_(0)
{
    if (outletPatch_ < 0)
    {
        ::granair::fail<::granair::InputError>
        (
            "constant/granularProperties, key 'outletPatch': no boundary patch named '", outletPatch, "'"
        );
    }
    const uniformDimensionedVectorField& g = meshObjects::gravity::New(mesh.time());
    if (mag(g.value()) > SMALL) up_ = -g.value()/mag(g.value());
    nearOutlet_ = stressFreeByConstruction(mesh, outletPatch_, orificeHeight_, up_);
    initialMass_ = powderMass(content);

    std::vector<::granair::Column> columns{
        {"t", "s"}, {"mass_flow_kg_s", "kg/s"}, {"discharged_kg", "kg"}, {"powder_mass_kg", "kg"},
        {"mass_balance_error", "-"}};
    if (air_)
    {
        columns.push_back({"outlet_dpdz_Pa_m", "Pa/m"});
        columns.push_back({"air_p_min_Pa", "Pa"});
    }
    for (const ::granair::Column& c : std::vector<::granair::Column>{
             {"outer_correctors", "-"}, {"outer_residual_U", "-"}, {"outer_residual_p", "-"},
             {"outer_converged", "-"}, {"tension_fraction", "-"}})
    {
        columns.push_back(c);
    }
    mkDir(directory);
    writer_ = std::make_unique<::granair::TimeSeriesWriter>(MPI_COMM_WORLD, directory/"timeSeries", columns);

    Info<< "PowderBalance: outlet patch " << outletPatch.c_str() << ", full-revolution scale " << scale_
        << ", initial powder mass " << initialMass_ << " kg" << nl << endl;
}

scalar PowderBalance::powderMass(const volScalarField& content) const
{
    return scale_*rhoPowder_*gSum(content.primitiveField()*mesh_.V().field());
}

scalar PowderBalance::relativeBalanceError(const volScalarField& content) const
{
    return (powderMass(content) + discharged_ - initialMass_)/initialMass_;
}

void PowderBalance::record
(
    const volScalarField& content,
    const surfaceScalarField& contentFlux,
    const volScalarField& alpha,
    const AirPercolation& air,
    const volScalarField& p,
    const StepStatistics& step
)
{
    const scalar dt = mesh_.time().deltaTValue();
    scalar outletFlux = 0;
    scalar boundaryFlux = 0;
    forAll(contentFlux.boundaryField(), patchi)
    {
        if (mesh_.boundaryMesh()[patchi].coupled()) continue;
        const scalar f = sum(contentFlux.boundaryField()[patchi]);
        boundaryFlux += f;
        if (patchi == outletPatch_) outletFlux = f;
    }
    reduce(outletFlux, sumOp<scalar>());
    reduce(boundaryFlux, sumOp<scalar>());
    lastFlow_ = scale_*rhoPowder_*outletFlux;
    discharged_ += scale_*rhoPowder_*boundaryFlux*dt;

    const scalar mass = powderMass(content);
    std::vector<double> row{mesh_.time().value(), lastFlow_, discharged_, mass, (mass + discharged_ - initialMass_)/initialMass_};
    if (air_)
    {
        // On the orifice plane where the mesh has faces there (the wedge
        // silo); else (the MCC cap is curved) on the outlet patch.
        const scalar onPlane = orificeHeight_ < VGREAT ? air.planeGradient(orificeHeight_, up_) : VGREAT;
        row.push_back(std::isfinite(onPlane) && onPlane < VGREAT ? onPlane : air.patchGradient(outletPatch_, up_));
        row.push_back(gMin(air.pAir().primitiveField()));
    }

    label packed = 0, tension = 0;
    forAll(alpha, celli)
    {
        if (alpha[celli] > 0.99 && !nearOutlet_[celli])
        {
            ++packed;
            if (p[celli] <= 0) ++tension;
        }
    }
    reduce(packed, sumOp<label>());
    reduce(tension, sumOp<label>());
    lastTensionFraction_ = packed > 0 ? scalar(tension)/packed : scalar(0);

    ++steps_;
    sumOuter_ += step.outerCorrectors;
    maxOuter_ = max(maxOuter_, step.outerCorrectors);
    if (!step.converged) ++unconvergedSteps_;
    for (const scalar v : {scalar(step.outerCorrectors), step.residualU, step.residualP,
                           scalar(step.converged ? 1 : 0), lastTensionFraction_})
    {
        row.push_back(v);
    }
    writer_->append(row);
}

void PowderBalance::reportIterations() const
{
    Info<< "outer correctors: " << steps_ << " steps, mean " << (steps_ ? sumOuter_/steps_ : 0) << ", most "
        << maxOuter_ << " per step; steps not converged within nOuterCorrectors: " << unconvergedSteps_ << endl;
}

} // namespace granair
} // namespace Foam
