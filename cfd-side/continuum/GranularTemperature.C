/*---------------------------------------------------------------------------*\
    granair: GranularTemperature (see GranularTemperature.H)
\*---------------------------------------------------------------------------*/
#include "GranularTemperature.H"

#include <string>

#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace granair
{

namespace
{

IOobject temperatureHeader(const fvMesh& mesh, const ::granair::Dictionary& rheology)
{
    IOobject io("T", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE);
    std::string error;
    if (!io.typeHeaderOk<volScalarField>(true))
    {
        error = std::string("granairContinuumFoam: ") + rheology.where("type")
              + ": rheology 'latzSchmidt' transports the granular temperature, but its field file '"
              + io.objectPath() + "' is missing or not a volScalarField; write " + mesh.time().timeName()
              + "/T (dimensions [0 2 -2 0 0 0 0], internalField >= TMin, e.g. uniform 1e-12; "
              + "walls zeroGradient, open boundaries inletOutlet)";
    }
    ::granair::raiseIfAny(MPI_COMM_WORLD, error);
    return io;
}

volScalarField::Internal internalField(const fvMesh& mesh, const word& name, const dimensionSet& dims)
{
    return volScalarField::Internal
    (
        IOobject(name, mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dims, Zero)
    );
}

} // namespace

GranularTemperature::GranularTemperature(const fvMesh& mesh, const ::granair::Dictionary& rheology)
:
    mesh_(mesh),
    model_(::granair::GranularTemperatureModel::fromDictionary(rheology)),
    T_(temperatureHeader(mesh, rheology), mesh)
{
    std::string error;
    const scalar tMin = model_.parameters().TMin;
    if (T_.dimensions() != dimVelocity*dimVelocity)
    {
        error = "granairContinuumFoam: field T (" + T_.objectPath() + ") must have dimensions [0 2 -2 0 0 0 0] (m2/s2)";
    }
    else if (!(gMin(T_.primitiveField()) >= tMin))
    {
        error = "granairContinuumFoam: field T (" + T_.objectPath() + ") has a value "
              + std::to_string(gMin(T_.primitiveField())) + " m2/s2 below TMin = " + std::to_string(tMin)
              + " m2/s2 (rheology latzSchmidt)";
    }
    ::granair::raiseIfAny(MPI_COMM_WORLD, error);
}

void GranularTemperature::solve
(
    const volScalarField& alpha,
    const surfaceScalarField& phi,
    const volScalarField& p,
    const scalarField& gammaDot
)
{
    const label nPasses = mesh_.solverDict(T_.name()).lookupOrDefault<label>("nTCorr", 2);
    const scalar tMin = model_.parameters().TMin;
    const dimensionSet dimT(dimVelocity*dimVelocity);

    volScalarField::Internal coeff(internalField(mesh_, "TddtCoeff", dimless));
    volScalarField::Internal heating(internalField(mesh_, "Theating", dimT/dimTime));
    volScalarField::Internal sink(internalField(mesh_, "TsinkRate", dimless/dimTime));
    volScalarField aLambda
    (
        IOobject("aLambda", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimViscosity, Zero),
        zeroGradientFvPatchScalarField::typeName
    );

    for (label pass = 0; pass < nPasses; ++pass)
    {
        std::string error;
        try
        {
            forAll(coeff, celli)
            {
                const scalar a = min(max(alpha[celli], scalar(0)), scalar(1));
                ::granair::GranularTemperatureModel::Cell c;
                try
                {
                    c = model_.evaluate(p[celli], T_[celli], gammaDot[celli]);
                }
                catch (const ::granair::InputError& e)
                {
                    ::granair::fail<::granair::InputError>
                    (
                        e.what(), " in cell ", celli, " at ", mesh_.C()[celli].x(), " ", mesh_.C()[celli].y(), " ",
                        mesh_.C()[celli].z(), " m, time ", mesh_.time().value(), " s"
                    );
                }
                coeff[celli] = 1.5*max(a*c.c, cFloor);
                heating[celli] = a*c.production;
                sink[celli] = a*c.sinkRate;
                aLambda[celli] = a*c.lambda;
            }
        }
        catch (const ::granair::InputError& e)
        {
            error = e.what();
        }
        ::granair::raiseIfAny(MPI_COMM_WORLD, error);
        aLambda.correctBoundaryConditions();

        fvScalarMatrix TEqn(fvm::ddt(T_) + fvm::div(phi, T_) - fvm::Sp(fvc::div(phi), T_));
        TEqn *= coeff;
        TEqn -= fvm::laplacian(fvc::interpolate(aLambda), T_);
        TEqn += fvm::Sp(sink, T_);
        TEqn -= heating;
        TEqn.solve();

        T_.primitiveFieldRef() = max(T_.primitiveField(), tMin);
        T_.correctBoundaryConditions();
    }
}

} // namespace granair
} // namespace Foam
