/*---------------------------------------------------------------------------*\
    granair: frictionalStressModels::muI (see MuIFrictionalStress.H)
\*---------------------------------------------------------------------------*/
#include "MuIFrictionalStress.H"

#include "FrictionalFields.H"
#include "GranairDictionary.H"
#include "core/Error.hpp"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace kineticTheoryModels
{
namespace frictionalStressModels
{
    defineTypeNameAndDebug(muI, 0);
    addToRunTimeSelectionTable(frictionalStressModel, muI, dictionary);
}
}
}

using Foam::kineticTheoryModels::frictionalStressModels::muI;

namespace
{

// The scalar laws, shared by the cells and the boundary faces.
struct PressureLaw
{
    double Fr, eta, p, delta, alphaMin, alphaMax;
    bool shear;
    double shearMin;  // p_I's onset in alpha
    double rhoP, d, phiMax, phiMin;

    double contact(double a) const
    {
        if (a <= alphaMin) return 0;
        return Fr*std::pow(a - alphaMin, eta)/std::pow(std::max(alphaMax - a, delta), p);
    }
    double contactPrime(double a) const
    {
        if (a <= alphaMin) return 0;
        const double gap = alphaMax - a;
        if (gap <= delta)  // denominator frozen at delta
        {
            return Fr*eta*std::pow(a - alphaMin, eta - 1)/std::pow(delta, p);
        }
        return Fr*(eta*std::pow(a - alphaMin, eta - 1)*gap + p*std::pow(a - alphaMin, eta))
            /std::pow(gap, p + 1);
    }
    double shearInduced(double a, double gammaDot) const
    {
        if (!shear || a <= shearMin) return 0;
        const double g = std::max(phiMax - a, delta);
        return rhoP*sqr((phiMax - phiMin)*d*gammaDot)/(g*g);
    }
    double shearInducedPrime(double a, double gammaDot) const
    {
        if (!shear || a <= shearMin || phiMax - a <= delta) return 0;
        const double g = phiMax - a;
        return 2*rhoP*sqr((phiMax - phiMin)*d*gammaDot)/(g*g*g);
    }
    static double sqr(double x) { return x*x; }
};

} // namespace


muI::muI(const Foam::dictionary& dict)
:
    frictionalStressModel(dict),
    coeffDict_(dict.optionalSubDict(typeName + "Coeffs")),
    Fr_("Fr", dimensionSet(1, -1, -2, 0, 0), coeffDict_),
    eta_("eta", dimless, coeffDict_),
    p_("p", dimless, coeffDict_),
    alphaDeltaMin_("alphaDeltaMin", dimless, coeffDict_),
    shearInduced_(coeffDict_.getOrDefault<Switch>("shearInducedPressure", false)),
    shearInducedAlphaMin_(coeffDict_.getOrDefault<scalar>("shearInducedAlphaMin", -1))
{
    readCoeffs();
}


void muI::readCoeffs()
{
    const ::granair::Dictionary rd = granairTwoFluid::toGranair(coeffDict_, "rheology");
    try
    {
        std::unique_ptr<::granair::Rheology> r = ::granair::rheologies().create(rd);
        auto* m = dynamic_cast<::granair::MuI*>(r.get());
        if (!m)
        {
            granairTwoFluid::fatalFromGranair
            (
                coeffDict_,
                rd.where("type") + ": frictionalStressModel muI needs rheology type muI, got '"
                    + r->name() + "'"
            );
        }
        r.release();
        rheology_.reset(m);
        rd.checkKnownKeys();
    }
    catch (const ::granair::Error& e)
    {
        granairTwoFluid::fatalFromGranair(coeffDict_, e.what());
    }
    if (coeffDict_.found("shearInducedAlphaMin") && !(shearInducedAlphaMin_ > 0 && shearInducedAlphaMin_ < 1))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "muICoeffs: shearInducedAlphaMin " << shearInducedAlphaMin_
            << ": expected a solid fraction in (0, 1), the onset of the shear-induced pressure" << exit(FatalIOError);
    }
    if (Fr_.value() <= 0 || eta_.value() < 1 || p_.value() < 0 || alphaDeltaMin_.value() <= 0)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "muICoeffs: expected Fr > 0 [Pa], eta >= 1, p >= 0, alphaDeltaMin > 0; got Fr "
            << Fr_.value() << ", eta " << eta_.value() << ", p " << p_.value()
            << ", alphaDeltaMin " << alphaDeltaMin_.value() << exit(FatalIOError);
    }
    phaseChecked_ = false;
}


void muI::checkPhase(const phaseModel& phase) const
{
    if (phaseChecked_) return;
    const auto& par = rheology_->parameters();
    const scalar rho = gAverage(phase.rho().primitiveField());
    const scalar d = gAverage(phase.d()().primitiveField());
    if (mag(rho - par.rhoP) > 1e-6*par.rhoP || mag(d - par.d) > 1e-6*par.d)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "muICoeffs.rheology: rhoP " << par.rhoP << " kg/m3 and d " << par.d
            << " m must be the particle phase's density and diameter (" << phase.name()
            << ": rho " << rho << " kg/m3 in thermophysicalProperties." << phase.name()
            << ", d " << d << " m in phaseProperties)" << exit(FatalIOError);
    }
    phaseChecked_ = true;
}


namespace
{
PressureLaw makeLaw
(
    const Foam::dimensionedScalar& Fr, const Foam::dimensionedScalar& eta,
    const Foam::dimensionedScalar& p, const Foam::dimensionedScalar& delta, bool shear,
    Foam::scalar shearMin,
    const Foam::dimensionedScalar& alphaMin, const Foam::dimensionedScalar& alphaMax,
    const granair::MuI& r
)
{
    const auto& par = r.parameters();
    return PressureLaw
    {
        Fr.value(), eta.value(), p.value(), delta.value(), alphaMin.value(), alphaMax.value(),
        shear, shearMin < 0 ? alphaMin.value() : shearMin, par.rhoP, par.d, par.phiMax, par.phiMin
    };
}

} // namespace


Foam::tmp<Foam::volScalarField> muI::pressure
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    const bool prime
) const
{
    checkPhase(phase);
    const PressureLaw law = makeLaw(Fr_, eta_, p_, alphaDeltaMin_, shearInduced_, shearInducedAlphaMin_, alphaMinFriction, alphaMax, *rheology_);
    const tmp<volScalarField> tg = granairTwoFluid::shearRate(phase.U());
    const auto pf = [&law](double a, double g) { return law.contact(a) + law.shearInduced(a, g); };
    const auto pfPrime = [&law](double a, double g) { return law.contactPrime(a) + law.shearInducedPrime(a, g); };
    if (prime)
    {
        granairTwoFluid::publishSecantRatio(phase, tg(), pf, pfPrime);
        return granairTwoFluid::pointwise("muI:pfPrime", phase, tg(), dimPressure, pfPrime);
    }
    return granairTwoFluid::pointwise("muI:pf", phase, tg(), dimPressure, pf);
}


Foam::tmp<Foam::volScalarField> muI::frictionalPressure
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    return pressure(phase, alphaMinFriction, alphaMax, false);
}


Foam::tmp<Foam::volScalarField> muI::frictionalPressurePrime
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    return pressure(phase, alphaMinFriction, alphaMax, true);
}


Foam::tmp<Foam::volScalarField> muI::nu
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    const volScalarField& pf,
    const volSymmTensorField& D
) const
{
    checkPhase(phase);
    const scalar rhoP = rheology_->parameters().rhoP;
    const tmp<volScalarField> tg = granairTwoFluid::shearRate(D);
    const volScalarField& gammaDot = tg();
    // pf is p_f/rho_p here (kineticTheoryModel divides by the phase density).
    const auto op = [&](double pfOverRho, double g)
    {
        const double p = pfOverRho*rhoP;
        return p > 0 ? rheology_->viscosity(p, g)/rhoP : 0.0;
    };
    try
    {
        tmp<volScalarField> tnu = granairTwoFluid::pointwise("muI:nu", pf, gammaDot, dimViscosity, op);
        granairTwoFluid::publish(phase, rhoP, pf, tnu());
        return tnu;
    }
    catch (const ::granair::Error& e)
    {
        FatalErrorInFunction << "frictionalStressModel muI: " << e.what() << exit(FatalError);
    }
    return tmp<volScalarField>(nullptr);
}


bool muI::read()
{
    coeffDict_ <<= dict_.optionalSubDict(typeName + "Coeffs");
    Fr_.read(coeffDict_);
    eta_.read(coeffDict_);
    p_.read(coeffDict_);
    alphaDeltaMin_.read(coeffDict_);
    shearInduced_ = coeffDict_.getOrDefault<Switch>("shearInducedPressure", false);
    shearInducedAlphaMin_ = coeffDict_.getOrDefault<scalar>("shearInducedAlphaMin", -1);
    readCoeffs();
    return true;
}
