/*---------------------------------------------------------------------------*\
    granair: GranularMixture (see GranularMixture.H)
\*---------------------------------------------------------------------------*/
#include "GranularMixture.H"

#include <cmath>
#include <string>

#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "rheology/LatzSchmidt.hpp"
#include "rheology/ShearRate.hpp"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace granair
{

namespace
{

volScalarField derivedField(const fvMesh& mesh, const word& name, const dimensionSet& dims, bool write)
{
    return volScalarField
    (
        IOobject
        (
            name, mesh.time().timeName(), mesh,
            IOobject::NO_READ, write ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dims, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
}

// The rheology as a pressure/shear-rate one, or null if it is latzSchmidt (the
// solver transports its temperature); any other kind is refused by name.
const ::granair::ViscoplasticRheology* viscoplastic
(
    const ::granair::Rheology& r,
    const ::granair::Dictionary& dict
)
{
    const auto* v = dynamic_cast<const ::granair::ViscoplasticRheology*>(&r);
    if (!v && r.name() != ::granair::LatzSchmidt::typeName)
    {
        std::string needs;
        for (const auto& in : r.inputs()) needs += " " + in;
        ::granair::fail<::granair::InputError>
        (
            dict.where("type"), ": rheology '", r.name(), "' needs the state (", needs,
            " ), but granairContinuumFoam provides only the pressure p and the shear rate gammaDot, ",
            "or the granular temperature of latzSchmidt; use muI or latzSchmidt"
        );
    }
    return v;
}

} // namespace

GranularMixture::GranularMixture(const fvMesh& mesh, const ::granair::Dictionary& properties)
:
    mesh_(mesh),
    rheologyOwner_(::granair::rheologies().create(properties.subDict("rheology"))),
    viscoplastic_(viscoplastic(*rheologyOwner_, properties.subDict("rheology"))),
    temperature_
    (
        viscoplastic_ ? nullptr : std::make_unique<GranularTemperature>(mesh, properties.subDict("rheology"))
    ),
    rhoPowder_(properties.subDict("powder").getDouble("rho", 1e-3, 1e5)),
    rhoAir_(properties.subDict("air").getDouble("rho", 1e-6, 1e4)),
    muAir_(properties.subDict("air").getDouble("mu", 1e-9, 1e3)),
    relax_(properties.getDouble("viscosityRelaxation", 0.5)),
    aitken_(properties.getBool("viscosityAitken", true)),
    deviatoric_(false),
    omega_(relax_),
    omegaMin_(0.05),
    omegaMax_(20),
    alpha_
    (
        IOobject("alpha.powder", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    rho_
    (
        IOobject("rho", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        alpha_*dimensionedScalar("rhoPowder", dimDensity, rhoPowder_)
      + (scalar(1) - alpha_)*dimensionedScalar("rhoAir", dimDensity, rhoAir_)
    ),
    eta_(derivedField(mesh, "eta", dimDynamicViscosity, true)),
    mu_(derivedField(mesh, "muMixture", dimDynamicViscosity, true)),
    I_(derivedField(mesh, "I", dimless, viscoplastic_ != nullptr)),
    gammaDot_(derivedField(mesh, "gammaDot", dimless/dimTime, true)),
    phiSolid_(derivedField(mesh, "phiSolid", dimless, true))
{
    if (!(relax_ > 0 && relax_ <= 1))
    {
        ::granair::fail<::granair::InputError>
        (
            properties.where("viscosityRelaxation"), ": value ", relax_, " outside (0, 1]"
        );
    }
    rho_.oldTime();
    // Before the first step: the powder at rest under load, viscosity at the
    // cap (both rheologies reach it at rest: gammaDot -> 0 at p > 0, or T at
    // its floor; muI at 1 kPa and gammaDot = 0), and the solid fraction of the
    // powder at rest (latzSchmidt: c0, the packed state). Both are replaced in
    // the first correctViscosity; only the fields written at t = 0 keep them.
    const scalar pRest = 1e3;
    const scalar etaRest =
        viscoplastic_ ? viscoplastic_->viscosity(pRest, 0) : temperature_->model().parameters().etaMax;
    const scalar phiRest =
        viscoplastic_ ? viscoplastic_->solidFraction(pRest, 0) : temperature_->model().closure().parameters().c0;
    mu_ = alpha_*dimensionedScalar("etaRest", dimDynamicViscosity, etaRest)
        + (scalar(1) - alpha_)*dimensionedScalar("muAir", dimDynamicViscosity, muAir_);
    mu_.correctBoundaryConditions();
    phiSolid_ = dimensionedScalar("phiRest", dimless, phiRest);
    phiSolid_.correctBoundaryConditions();
}

void GranularMixture::correctDensity()
{
    const volScalarField a(min(max(alpha_, scalar(0)), scalar(1)));
    rho_ == a*dimensionedScalar("rhoPowder", dimDensity, rhoPowder_) + (scalar(1) - a)*dimensionedScalar("rhoAir", dimDensity, rhoAir_);
}

void GranularMixture::relaxViscosity(const scalarField& target, bool firstCorrector)
{
    scalarField& eta = eta_.primitiveFieldRef();
    // In log space: eta spans orders of magnitude, and a step in ln(eta) is
    // a relative change of the viscosity.
    const scalarField r(log(max(target, VSMALL)) - log(max(eta, VSMALL)));
    scalar omega = relax_;
    if (aitken_ && !firstCorrector && residual_.size() == r.size())
    {
        const scalarField w(min(max(alpha_.primitiveField(), scalar(0)), scalar(1)));
        const scalarField dr(r - residual_);
        const scalar drdr = gSum(w*dr*dr);
        omega = drdr > 0 ? -omega_*gSum(w*residual_*dr)/drdr : omega_;
        omega = min(max(omega, omegaMin_), omegaMax_);
    }
    // Keep the iterate inside the range the rheology itself returns.
    const scalar lo = log(max(gMin(target), VSMALL));
    const scalar hi = log(max(gMax(target), VSMALL));
    eta = exp(min(max(log(max(eta, VSMALL)) + omega*r, lo), hi));
    residual_ = r;
    omega_ = omega;
}

tmp<surfaceScalarField> GranularMixture::faceViscosity() const
{
    return tmp<surfaceScalarField>::New("muf", scalar(1)/fvc::interpolate(scalar(1)/mu_));
}

void GranularMixture::correctViscosity
(
    const volVectorField& U,
    const surfaceScalarField& phiFlux,
    const volScalarField& p,
    bool firstCorrector
)
{
    const volTensorField gradU(fvc::grad(U));
    const scalarField& alpha = alpha_.primitiveField();
    const scalarField& pc = p.primitiveField();
    scalarField& eta = eta_.primitiveFieldRef();
    scalarField& mu = mu_.primitiveFieldRef();
    scalarField& I = I_.primitiveFieldRef();
    scalarField& gd = gammaDot_.primitiveFieldRef();
    scalarField& phi = phiSolid_.primitiveFieldRef();

    forAll(gd, celli)
    {
        const tensor& g = gradU[celli];
        Eigen::Matrix3d m;
        m << g.xx(), g.xy(), g.xz(), g.yx(), g.yy(), g.yz(), g.zx(), g.zy(), g.zz();
        gd[celli] = deviatoric_ ? ::granair::deviatoricShearRate(m) : ::granair::shearRate(m);
    }
    if (temperature_)
    {
        // T at the latest U and p first; collective, raises on all ranks.
        temperature_->solve(alpha_, phiFlux, p, gd);
    }

    scalarField etaTarget(eta.size());
    std::string error;
    try
    {
        forAll(eta, celli)
        {
            try
            {
                scalar etaNew;
                if (viscoplastic_)
                {
                    etaNew = viscoplastic_->viscosity(pc[celli], gd[celli]);
                    // -1 marks the stress-free cells (p <= 0), where I is infinite.
                    const scalar In = viscoplastic_->inertialNumber(pc[celli], gd[celli]);
                    I[celli] = std::isfinite(In) ? In : -1;
                    phi[celli] = viscoplastic_->solidFraction(pc[celli], gd[celli]);
                }
                else
                {
                    const auto cell = temperature_->cell(celli, pc[celli], gd[celli]);
                    etaNew = cell.eta;
                    phi[celli] = cell.c;
                }
                etaTarget[celli] = etaNew;
            }
            catch (const ::granair::InputError& e)
            {
                ::granair::fail<::granair::InputError>
                (
                    e.what(), " in cell ", celli, " at ", mesh_.C()[celli].x(), " ", mesh_.C()[celli].y(), " ",
                    mesh_.C()[celli].z(), " m, time ", mesh_.time().value(), " s"
                );
            }
        }
    }
    catch (const ::granair::InputError& e)
    {
        error = e.what();
    }
    // Every rank reaches this point, so an error on one rank ends all of them together.
    ::granair::raiseIfAny(MPI_COMM_WORLD, error);

    relaxViscosity(etaTarget, firstCorrector);
    forAll(eta, celli)
    {
        const scalar a = min(max(alpha[celli], scalar(0)), scalar(1));
        // Never below the air's: a rheology may return 0 (latzSchmidt where
        // c = 0), and the harmonic face viscosity divides by mu.
        mu[celli] = a*max(eta[celli], muAir_) + (1 - a)*muAir_;
    }

    for (volScalarField* f : {&eta_, &mu_, &I_, &gammaDot_, &phiSolid_})
    {
        f->correctBoundaryConditions();
    }
}

} // namespace granair
} // namespace Foam
