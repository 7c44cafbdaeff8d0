/*---------------------------------------------------------------------------*\
    granair: dragModels::granairDrag (see GranairDrag.H)
\*---------------------------------------------------------------------------*/
#include "GranairDrag.H"

#include "GranairDictionary.H"
#include "addToRunTimeSelectionTable.H"
#include "coupler/BedDrag.hpp"
#include "core/Error.hpp"
#include "phasePair.H"
#include "surfaceInterpolate.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(granairDrag, 0);
    addToRunTimeSelectionTable(dragModel, granairDrag, dictionary);
}
}

Foam::dragModels::granairDrag::granairDrag
(
    const dictionary& dict,
    const phasePair& pair,
    const bool registerObject
)
:
    dragModel(dict, pair, registerObject),
    diameter_(dict.getOrDefault<scalar>("diameter", -1)),
    scale_(dict.getOrDefault<scalar>("scale", 1))
{
    if (dict.found("diameter") && !(diameter_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "drag " << pair.name() << ": diameter " << diameter_
            << " m: expected a particle diameter > 0 (or no entry: the phase's d)" << exit(FatalIOError);
    }
    if (!(scale_ > 0 && scale_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "drag " << pair.name() << ": scale " << scale_
            << ": expected 0 < scale <= 1 (1, the default: the law's drag; less: a dry reference)"
            << exit(FatalIOError);
    }
    const ::granair::Dictionary law = granairTwoFluid::toGranair(dict, "law");
    try
    {
        law_ = ::granair::dragLaws().create(law);
        law.checkKnownKeys();
    }
    catch (const std::exception& e)
    {
        granairTwoFluid::fatalFromGranair(dict, e.what());
    }
    Info<< "granair drag for " << pair.name() << ": coupling-library law "
        << law_->name().c_str();
    if (scale_ != 1)
    {
        Info<< " times " << scale_;
    }
    Info<< endl;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::granairDrag::K() const
{
    const phaseModel& disp = pair_.dispersed();
    const phaseModel& cont = pair_.continuous();
    const tmp<volScalarField> td = disp.d();
    const volScalarField& d = td();
    const tmp<volScalarField> tmuC = cont.mu();
    const volScalarField& muC = tmuC();
    const volScalarField& rhoC = cont.rho();
    const volScalarField magSlip(mag(cont.U() - disp.U()));
    const scalar residual = disp.residualAlpha().value();

    tmp<volScalarField> tK
    (
        new volScalarField
        (
            IOobject
            (
                IOobject::groupName("Kgranair", pair_.name()),
                disp.mesh().time().timeName(),
                disp.mesh()
            ),
            disp.mesh(),
            dimensionedScalar(dimK, Zero)
        )
    );
    volScalarField& K = tK.ref();

    // One evaluation per cell and boundary face, through the same function
    // as granairAirFoam's prescribed bed and the continuum solver.
    const auto eval = [&](scalar alphaD, scalar di, scalar slip, scalar rho, scalar mu)
    {
        const scalar eps = 1.0 - min(max(alphaD, residual), 1.0 - SMALL);
        if (diameter_ > 0) di = diameter_;
        ::granair::FluidProperties fluid;
        fluid.rho = rho;
        fluid.mu = mu;
        return scale_*::granair::bedMomentumExchange(*law_, di, eps, slip, fluid);
    };
    try
    {
        forAll(K, i)
        {
            K[i] = eval(disp[i], d[i], magSlip[i], rhoC[i], muC[i]);
        }
        forAll(K.boundaryField(), patchi)
        {
            fvPatchScalarField& Kp = K.boundaryFieldRef()[patchi];
            const fvPatchScalarField& ap = disp.boundaryField()[patchi];
            forAll(Kp, facei)
            {
                Kp[facei] = eval
                (
                    ap[facei], d.boundaryField()[patchi][facei],
                    magSlip.boundaryField()[patchi][facei],
                    rhoC.boundaryField()[patchi][facei], muC.boundaryField()[patchi][facei]
                );
            }
        }
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << "drag " << pair_.name() << ": " << e.what() << exit(FatalError);
    }
    return tK;
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::granairDrag::Ki() const
{
    return K()/max(pair_.dispersed(), pair_.dispersed().residualAlpha());
}


Foam::tmp<Foam::volScalarField> Foam::dragModels::granairDrag::CdRe() const
{
    // Inverse of dragModel::Ki() = 0.75 CdRe rho_c nu_c/d^2 (no swarm factor).
    return Ki()*sqr(pair_.dispersed().d())
        /(0.75*pair_.continuous().rho()*pair_.continuous().nu());
}


Foam::tmp<Foam::surfaceScalarField> Foam::dragModels::granairDrag::Kf() const
{
    return fvc::interpolate(K());
}
