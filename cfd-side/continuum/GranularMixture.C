/*---------------------------------------------------------------------------*\
    granair: GranularMixture (see GranularMixture.H)
\*---------------------------------------------------------------------------*/
#include "GranularMixture.H"

#include <string>

#include "core/Collective.hpp"
#include "core/Error.hpp"
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

const ::granair::ViscoplasticRheology* viscoplastic
(
    const ::granair::Rheology& r,
    const ::granair::Dictionary& dict
)
{
    const auto* v = dynamic_cast<const ::granair::ViscoplasticRheology*>(&r);
    if (!v)
    {
        std::string needs;
        for (const auto& in : r.inputs()) needs += " " + in;
        ::granair::fail<::granair::InputError>
        (
            dict.where("type"), ": rheology '", r.name(), "' needs the state (", needs,
            " ), but granairContinuumFoam provides only the pressure p and the shear rate gammaDot; ",
            "use a pressure/shear-rate rheology (muI)"
        );
    }
    return v;
}

} // namespace

GranularMixture::GranularMixture(const fvMesh& mesh, const ::granair::Dictionary& properties)
:
    mesh_(mesh),
    rheologyOwner_(::granair::rheologies().create(properties.subDict("rheology"))),
    rheology_(viscoplastic(*rheologyOwner_, properties.subDict("rheology"))),
    rhoPowder_(properties.subDict("powder").getDouble("rho", 1e-3, 1e5)),
    rhoAir_(properties.subDict("air").getDouble("rho", 1e-6, 1e4)),
    muAir_(properties.subDict("air").getDouble("mu", 1e-9, 1e3)),
    relax_(properties.getDouble("viscosityRelaxation", 1.0)),
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
    I_(derivedField(mesh, "I", dimless, true)),
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
    // Before the first step: the powder at rest, viscosity at the cap.
    mu_ = alpha_*dimensionedScalar("etaRest", dimDynamicViscosity, rheology_->viscosity(0, 0))
        + (scalar(1) - alpha_)*dimensionedScalar("muAir", dimDynamicViscosity, muAir_);
    mu_.correctBoundaryConditions();
    phiSolid_ = dimensionedScalar("phiRest", dimless, rheology_->solidFraction(0, 0));
    phiSolid_.correctBoundaryConditions();
}

void GranularMixture::correctDensity()
{
    const volScalarField a(min(max(alpha_, scalar(0)), scalar(1)));
    rho_ == a*dimensionedScalar("rhoPowder", dimDensity, rhoPowder_) + (scalar(1) - a)*dimensionedScalar("rhoAir", dimDensity, rhoAir_);
}

void GranularMixture::correctViscosity(const volVectorField& U, const volScalarField& p)
{
    const volTensorField gradU(fvc::grad(U));
    const scalarField& alpha = alpha_.primitiveField();
    const scalarField& pc = p.primitiveField();
    scalarField& eta = eta_.primitiveFieldRef();
    scalarField& mu = mu_.primitiveFieldRef();
    scalarField& I = I_.primitiveFieldRef();
    scalarField& gd = gammaDot_.primitiveFieldRef();
    scalarField& phi = phiSolid_.primitiveFieldRef();

    std::string error;
    try
    {
        forAll(eta, celli)
        {
            const tensor& g = gradU[celli];
            Eigen::Matrix3d m;
            m << g.xx(), g.xy(), g.xz(), g.yx(), g.yy(), g.yz(), g.zx(), g.zy(), g.zz();
            gd[celli] = ::granair::shearRate(m);
            try
            {
                const scalar etaNew = rheology_->viscosity(pc[celli], gd[celli]);
                eta[celli] = relax_*etaNew + (1 - relax_)*eta[celli];
                I[celli] = rheology_->inertialNumber(pc[celli], gd[celli]);
                phi[celli] = rheology_->solidFraction(pc[celli], gd[celli]);
            }
            catch (const ::granair::InputError& e)
            {
                ::granair::fail<::granair::InputError>
                (
                    e.what(), " in cell ", celli, " at ", mesh_.C()[celli].x(), " ", mesh_.C()[celli].y(), " ",
                    mesh_.C()[celli].z(), " m, time ", mesh_.time().value(), " s"
                );
            }
            const scalar a = min(max(alpha[celli], scalar(0)), scalar(1));
            mu[celli] = a*eta[celli] + (1 - a)*muAir_;
        }
    }
    catch (const ::granair::InputError& e)
    {
        error = e.what();
    }
    // Every rank reaches this point, so an error on one rank ends all of them together.
    ::granair::raiseIfAny(MPI_COMM_WORLD, error);

    for (volScalarField* f : {&eta_, &mu_, &I_, &gammaDot_, &phiSolid_})
    {
        f->correctBoundaryConditions();
    }
}

} // namespace granair
} // namespace Foam
