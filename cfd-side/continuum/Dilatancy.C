/*---------------------------------------------------------------------------*\
    granair: Dilatancy (see Dilatancy.H)
\*---------------------------------------------------------------------------*/
#include "Dilatancy.H"

#include "GranularMixture.H"
#include "core/Error.hpp"
#include "upwind.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace granair
{

namespace
{

std::unique_ptr<volScalarField> cellField(const fvMesh& mesh, const word& name, const dimensionSet& dims, scalar value)
{
    return std::make_unique<volScalarField>
    (
        IOobject(name, mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh,
        dimensionedScalar(name, dims, value),
        zeroGradientFvPatchScalarField::typeName
    );
}

} // namespace

Dilatancy::Dilatancy(const fvMesh& mesh, const ::granair::Dictionary& properties, GranularMixture& mixture)
:
    mesh_(mesh),
    enabled_(properties.getBool("dilatancy", false)),
    rate_(4.09),
    relax_(1),
    rhoP_(0),
    phi0_(1)
{
    if (!enabled_) return;
    if (mixture.temperature())
    {
        ::granair::fail<::granair::InputError>
        (
            properties.where("dilatancy"), ": dilatancy needs a pressure/shear-rate rheology (muI); '",
            mixture.rheology().name(), "' takes its solid fraction from its equation of state"
        );
    }
    rate_ = properties.getDouble("dilatancyRate", 4.09);
    if (!(rate_ > 0 && rate_ < 1e6))
    {
        ::granair::fail<::granair::InputError>(properties.where("dilatancyRate"), ": value ", rate_, " outside (0, 1e6)");
    }
    relax_ = properties.getDouble("dilatancyRelaxation", relax_);
    if (!(relax_ > 0 && relax_ <= 1))
    {
        ::granair::fail<::granair::InputError>(properties.where("dilatancyRelaxation"), ": value ", relax_, " outside (0, 1]");
    }
    const auto& rheology = properties.subDict("rheology");
    rhoP_ = rheology.getDouble("rhoP", 1e-3, 1e5);
    phi0_ = mixture.rhoPowder()/rhoP_;
    if (!(phi0_ > 0 && phi0_ <= 1))
    {
        ::granair::fail<::granair::InputError>
        (
            properties.subDict("powder").where("rho"), ": the bulk density ", mixture.rhoPowder(),
            " kg/m3 must not exceed the particle density rheology { rhoP } ", rhoP_,
            " kg/m3 (dilatancy on: the initial solid fraction is their ratio)"
        );
    }

    mixture.useDeviatoricShearRate();
    const volScalarField& alpha = mixture.alpha();
    IOobject io("alpha.grains", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE);
    if (io.typeHeaderOk<volScalarField>(true))
    {
        grains_ = std::make_unique<volScalarField>(io, mesh);
    }
    else
    {
        grains_ = cellField(mesh, "alpha.grains", dimless, 0);
        *grains_ = min(max(alpha, scalar(0)), scalar(1))*phi0_;
        grains_->correctBoundaryConditions();
    }
    phi_ = cellField(mesh, "phiPowder", dimless, phi0_);
    source_ = cellField(mesh, "dilatation", dimless/dimTime, 0);
    grainFlux_ = std::make_unique<surfaceScalarField>
    (
        IOobject("grainFlux", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar("grainFlux", dimVolume/dimTime, 0)
    );
    correctPhi(alpha);
    Info<< "Dilatancy: on, the powder's solid fraction relaxes to phi(I) at rate k = " << rate_
        << " (div U = -(alpha/phi) Dphi/Dt, relaxed by " << relax_ << " per corrector), initial packing rho_b/rho_p = "
        << phi0_ << nl << endl;
}

void Dilatancy::correctPhi(const volScalarField& alpha)
{
    const scalarField& a = alpha.primitiveField();
    const scalarField& m = grains_->primitiveField();
    scalarField& phi = phi_->primitiveFieldRef();
    forAll(phi, celli)
    {
        phi[celli] = a[celli] > 1e-6 ? min(max(m[celli]/a[celli], scalar(0)), scalar(1)) : phi0_;
    }
    phi_->correctBoundaryConditions();
}

void Dilatancy::transport(const volScalarField& alpha, const surfaceScalarField& alphaPhi)
{
    // The grains move with the powder phase at the solid fraction of the
    // cell they leave (upwind): conservative, and bounded by the phases'
    // packings where div U = 0.
    *grainFlux_ = alphaPhi*upwind<scalar>(mesh_, alphaPhi).interpolate(*phi_);
    grains_->primitiveFieldRef() -= mesh_.time().deltaTValue()*fvc::div(*grainFlux_)().primitiveField();
    grains_->correctBoundaryConditions();
    correctPhi(alpha);
}

void Dilatancy::correctDensity(volScalarField& rho, scalar rhoAir) const
{
    const volScalarField m(min(max(*grains_, scalar(0)), scalar(1)));
    rho == m*dimensionedScalar("rhoP", dimDensity, rhoP_) + (scalar(1) - m)*dimensionedScalar("rhoAir", dimDensity, rhoAir);
}

tmp<surfaceScalarField> Dilatancy::massFlux(const surfaceScalarField& phi, scalar rhoAir) const
{
    return tmp<surfaceScalarField>::New
    (
        "rhoPhi",
        *grainFlux_*dimensionedScalar("rhoP", dimDensity, rhoP_)
      + (phi - *grainFlux_)*dimensionedScalar("rhoAir", dimDensity, rhoAir)
    );
}

void Dilatancy::correctSource(const GranularMixture& mixture, scalar deltaT)
{
    const scalarField& a = mixture.alpha().primitiveField();
    const scalarField& gammaDot = mixture.shearRate().primitiveField();
    const scalarField& targetPhi = mixture.solidFraction().primitiveField();
    const scalarField& I = mixture.inertialNumber().primitiveField();
    const scalarField& phi = phi_->primitiveField();
    scalarField& S = source_->primitiveFieldRef();
    forAll(S, celli)
    {
        // Stress-free cells (p <= 0, I written as -1) keep their packing:
        // phi(I) has no meaning there (Dilatancy.H).
        const scalar r = I[celli] < 0 ? 0 : rate_*gammaDot[celli];
        const scalar target = min(max(a[celli], scalar(0)), scalar(1))*r*(phi[celli] - targetPhi[celli])/(1 + deltaT*r*phi[celli]);
        S[celli] += relax_*(target - S[celli]);
    }
    source_->correctBoundaryConditions();
}

} // namespace granair
} // namespace Foam
