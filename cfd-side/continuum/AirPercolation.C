/*---------------------------------------------------------------------------*\
    granair: AirPercolation (see AirPercolation.H)
\*---------------------------------------------------------------------------*/
#include "AirPercolation.H"

#include <limits>

#include <string>

#include "GranularMixture.H"
#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "coupler/BedDrag.hpp"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace granair
{

namespace
{

bool readModel(const ::granair::Dictionary& air)
{
    const std::string model = air.getString("model", "none");
    if (model != "none" && model != "darcyErgun")
    {
        ::granair::fail<::granair::InputError>
        (
            air.where("model"), ": unknown air model '", model, "', expected one of: none darcyErgun"
        );
    }
    return model == "darcyErgun";
}

volScalarField cellField(const fvMesh& mesh, const word& name, const dimensionSet& dims, scalar value, bool write)
{
    return volScalarField
    (
        IOobject(name, mesh.time().timeName(), mesh, IOobject::NO_READ, write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE),
        mesh,
        dimensionedScalar(name, dims, value),
        zeroGradientFvPatchScalarField::typeName
    );
}

} // namespace

AirPercolation::AirPercolation
(
    const fvMesh& mesh,
    const ::granair::Dictionary& properties,
    const GranularMixture& mixture
)
:
    mesh_(mesh),
    enabled_(readModel(properties.subDict("air"))),
    d_(0),
    air_{mixture.rhoAir(), mixture.muAir()},
    dilatancy_(true),
    dilatancyRate_(4.09),
    bulkSolidFraction_(0),
    threshold_(0.5),
    pAir_
    (
        enabled_
      ? volScalarField
        (
            IOobject("p_air", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
            mesh
        )
      : cellField(mesh, "p_air", dimPressure, 0, false)
    ),
    K_(cellField(mesh, "K", dimDensity/dimTime, 0, enabled_)),
    eps_(cellField(mesh, "airFraction", dimless, 1, enabled_)),
    packing_(cellField(mesh, "packing", dimless, 0, enabled_))
{
    if (!enabled_) return;

    const ::granair::Dictionary& air = properties.subDict("air");
    drag_ = ::granair::dragLaws().create(air.subDict("drag"));
    d_ = air.getDouble("diameter", 1e-7, 1.0);
    const std::string phiModel = air.getString("solidFraction", "dilatancy");
    if (phiModel == "bulk")
    {
        dilatancy_ = false;
        const scalar rhoP = air.getDouble("particleDensity", mixture.rhoPowder(), 1e5);
        bulkSolidFraction_ = mixture.rhoPowder()/rhoP;
    }
    else if (phiModel != "dilatancy")
    {
        ::granair::fail<::granair::InputError>
        (
            air.where("solidFraction"), ": unknown value '", phiModel, "', expected one of: dilatancy bulk"
        );
    }
    else if (air.has("dilatancyRate"))
    {
        dilatancyRate_ = air.getDouble("dilatancyRate", 0.0, 1e6);
    }
    threshold_ = air.getDouble("powderThreshold", 1e-6, 1.0);
    mesh_.setFluxRequired(pAir_.name());

    // The packing starts at phi(I) of the initial state (the rest value
    // before the first viscosity update), so the first step sees no jump.
    if (dilatancy_)
    {
        packing_ = mixture.solidFraction();
    }
    else
    {
        packing_ = dimensionedScalar("phiBulk", dimless, bulkSolidFraction_);
    }
    packing_.correctBoundaryConditions();
    const volScalarField a(min(max(mixture.alpha(), scalar(0)), scalar(1)));
    eps_ = scalar(1) - a*packing_;
    eps_.correctBoundaryConditions();
}

tmp<volScalarField> AirPercolation::solidFraction(const GranularMixture& mixture, scalar dt) const
{
    if (!dilatancy_)
    {
        return tmp<volScalarField>::New(cellField(mesh_, "phiSolidAir", dimless, bulkSolidFraction_, false));
    }
    // d(phi)/dt = -k phi gammaDot (phi - phi(I)), implicit with the rate at the old phi:
    // phi_new = (phi + r dt phi(I)) / (1 + r dt), r = k phi gammaDot >= 0; bounded
    // between phi and phi(I) for any dt.
    tmp<volScalarField> tphi(tmp<volScalarField>::New("phiSolidAir", packing_));
    scalarField& phi = tphi.ref().primitiveFieldRef();
    const scalarField& target = mixture.solidFraction().primitiveField();
    const scalarField& gammaDot = mixture.shearRate().primitiveField();
    forAll(phi, celli)
    {
        const scalar rdt = dilatancyRate_*phi[celli]*gammaDot[celli]*dt;
        phi[celli] = (phi[celli] + rdt*target[celli])/(1 + rdt);
    }
    tphi.ref().correctBoundaryConditions();
    return tphi;
}

void AirPercolation::solve
(
    const GranularMixture& mixture,
    const surfaceScalarField& alphaPhi,
    const surfaceScalarField& phi
)
{
    if (!enabled_) return;

    const dimensionedScalar dt = mesh_.time().deltaT();
    const volScalarField a(min(max(mixture.alpha(), scalar(0)), scalar(1)));
    const volScalarField phiS(solidFraction(mixture, dt.value()));
    volScalarField epsNew(scalar(1) - a*phiS);
    epsNew.correctBoundaryConditions();

    // d(eps)/dt + div(eps U) with eps U = U - alpha phi U, the powder part
    // through the MULES flux alphaPhi so a constant phi gives div(phi) only.
    const volScalarField source
    (
        (epsNew - eps_)/dt + fvc::div(phi) - fvc::div(alphaPhi*fvc::interpolate(phiS))
    );

    // Drag coefficient at the lagged slip; zero in the air (K(eps = 1) = 0).
    const volVectorField gradPa(fvc::grad(pAir_));
    scalarField& K = K_.primitiveFieldRef();
    DynamicList<label> airCells;
    std::string error;
    try
    {
        forAll(K, celli)
        {
            if (a[celli] < threshold_)
            {
                K[celli] = 0;
                airCells.append(celli);
                continue;
            }
            const scalar eps = epsNew[celli];
            const scalar slip = K[celli] > 0 ? eps*mag(gradPa[celli])/K[celli] : 0;
            try
            {
                K[celli] = ::granair::bedMomentumExchange(*drag_, d_, eps, slip, air_);
            }
            catch (const ::granair::InputError& e)
            {
                ::granair::fail<::granair::InputError>
                (
                    "air model darcyErgun: ", e.what(), " in cell ", celli, " (alpha ", a[celli], ", time ",
                    mesh_.time().value(), " s)"
                );
            }
        }
    }
    catch (const ::granair::InputError& e)
    {
        error = e.what();
    }
    ::granair::raiseIfAny(MPI_COMM_WORLD, error);
    K_.correctBoundaryConditions();

    // Face conductivity eps^2/K from the interpolated resistance K/eps^2
    // (harmonic mean: a face next to an air cell gets twice the powder value).
    const volScalarField resistance(K_/sqr(epsNew));
    const dimensionedScalar minResistance("minResistance", resistance.dimensions(), 1e-3);
    const surfaceScalarField conductivity(scalar(1)/max(fvc::interpolate(resistance), minResistance));

    fvScalarMatrix pEqn(fvm::laplacian(conductivity, pAir_) == source);
    pEqn.setValues(airCells, scalarField(airCells.size(), 0.0));
    pEqn.solve();

    eps_ = epsNew;
    packing_ = phiS;
}

tmp<surfaceScalarField> AirPercolation::faceForce() const
{
    if (!enabled_)
    {
        return tmp<surfaceScalarField>::New
        (
            IOobject("airForce", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedScalar(dimPressure/dimLength, Zero)
        );
    }
    return -fvc::snGrad(pAir_);
}

scalar AirPercolation::patchGradient(label patchi, const vector& direction) const
{
    const fvPatch& patch = mesh_.boundary()[patchi];
    const scalarField dpdn(pAir_.boundaryField()[patchi].snGrad());
    const scalarField area(patch.magSf());
    const scalar totalArea = gSum(area);
    return totalArea > 0 ? gSum(area*dpdn*(patch.nf() & direction))/totalArea : 0;
}

scalar AirPercolation::planeGradient(scalar height, const vector& direction) const
{
    // Internal faces on the plane (x.direction = height) whose normal is along direction.
    const surfaceScalarField dpdn(fvc::snGrad(pAir_));
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& magSf = mesh_.magSf().primitiveField();
    const scalar tol = 1e-6*Foam::cbrt(gAverage(mesh_.V().field()));
    scalar sumArea = 0, sum = 0;
    forAll(Cf, facei)
    {
        const scalar along = (Sf[facei] & direction)/magSf[facei];
        if (mag((Cf[facei] & direction) - height) < tol && mag(along) > 0.999)
        {
            sumArea += magSf[facei];
            sum += magSf[facei]*dpdn[facei]*along;
        }
    }
    reduce(sumArea, sumOp<scalar>());
    reduce(sum, sumOp<scalar>());
    return sumArea > 0 ? sum/sumArea : std::numeric_limits<scalar>::quiet_NaN();
}

} // namespace granair
} // namespace Foam
