/*---------------------------------------------------------------------------*\
    granair: frictionalStressModels::latzSchmidt (see LatzSchmidtFrictionalStress.H)
\*---------------------------------------------------------------------------*/
#include "LatzSchmidtFrictionalStress.H"

#include <cmath>

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
    defineTypeNameAndDebug(latzSchmidt, 0);
    addToRunTimeSelectionTable(frictionalStressModel, latzSchmidt, dictionary);
}
}
}

using Foam::kineticTheoryModels::frictionalStressModels::latzSchmidt;

namespace
{
// Step of the central difference of p in c: small against the packing range
// c0..cMax (~0.02) and against the cap distance, large against round-off.
constexpr double dc = 1e-7;
}


latzSchmidt::latzSchmidt(const Foam::dictionary& dict)
:
    frictionalStressModel(dict),
    coeffDict_(dict.optionalSubDict(typeName + "Coeffs"))
{
    readCoeffs();
}


void latzSchmidt::readCoeffs()
{
    const ::granair::Dictionary rd = granairTwoFluid::toGranair(coeffDict_, "rheology");
    try
    {
        model_ = std::make_unique<::granair::GranularTemperatureModel>
        (
            ::granair::GranularTemperatureModel::fromDictionary(rd)
        );
        rd.checkKnownKeys();
    }
    catch (const ::granair::Error& e)
    {
        granairTwoFluid::fatalFromGranair(coeffDict_, e.what());
    }
    alphaDeltaMin_ = coeffDict_.get<scalar>("alphaDeltaMin");
    const auto& par = closure().parameters();
    if (!(alphaDeltaMin_ > 0 && alphaDeltaMin_ < par.cMax - par.c0))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "latzSchmidtCoeffs: alphaDeltaMin " << alphaDeltaMin_ << ", expected 0 < alphaDeltaMin < cMax - c0 = "
            << par.cMax - par.c0 << exit(FatalIOError);
    }
    phaseChecked_ = false;
}


void latzSchmidt::checkPhase(const phaseModel& phase) const
{
    if (phaseChecked_) return;
    const scalar rhoP = model_->parameters().rhoP;
    const scalar rho = gAverage(phase.rho().primitiveField());
    if (mag(rho - rhoP) > 1e-6*rhoP)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "latzSchmidtCoeffs.rheology: rhoP " << rhoP << " kg/m3 must be the particle phase's density ("
            << phase.name() << ": rho " << rho << " kg/m3 in thermophysicalProperties." << phase.name() << ")"
            << exit(FatalIOError);
    }
    phaseChecked_ = true;
}


double latzSchmidt::cap() const
{
    return closure().parameters().cMax - alphaDeltaMin_;
}


double latzSchmidt::closurePressure(const double c, const double g) const
{
    const double tMin = model_->parameters().TMin;
    const double T = g > 0 ? std::max(closure().steadyShearTemperature(c, g), tMin) : tMin;
    return closure().values(c, T).p;
}


double latzSchmidt::pressure(const double c, const double g, const double cMin) const
{
    if (!(c > cMin)) return 0;
    const double top = cap();
    if (c <= top) return closurePressure(c, g);
    // beyond the cap: the tangent at the cap (the library refuses c >= cMax)
    return closurePressure(top, g) + pressurePrime(top, g, cMin)*(c - top);
}


double latzSchmidt::pressurePrime(const double c, const double g, const double cMin) const
{
    if (!(c > cMin)) return 0;
    const double top = cap();
    const double x = std::min(c, top);
    // central where both sides are inside (cMin, cap], one-sided at either end
    // (p jumps from 0 to its kinetic part at cMin: that step is not a slope)
    const double lo = x - dc > cMin ? x - dc : x, hi = x + dc <= top ? x + dc : x;
    return (closurePressure(hi, g) - closurePressure(lo, g))/(hi - lo);
}


double latzSchmidt::viscosity(const double pfOverRho, const double g) const
{
    if (!(pfOverRho > 0)) return 0;
    const double cap = model_->parameters().etaMax/model_->parameters().rhoP;
    const double tau = closure().tanFrictionAngle()*pfOverRho;  // shear stress / rho_p [m2/s2]
    return tau < cap*g ? tau/g : cap;
}


template<class Law>
Foam::tmp<Foam::volScalarField> latzSchmidt::field
(
    const word& name,
    const phaseModel& phase,
    const scalar cMin,
    Law law
) const
{
    if (!(cMin < cap()))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "frictionalStressModel latzSchmidt: alphaMinFriction " << cMin
            << " (kineticTheoryCoeffs) must be below the packing cap cMax - alphaDeltaMin = " << cap()
            << " (expected at or below c0 = " << closure().parameters().c0 << ")" << exit(FatalIOError);
    }
    checkPhase(phase);
    const tmp<volScalarField> tg = granairTwoFluid::shearRate(phase.U());
    try
    {
        // p_f is rho_p times the closure's pressure per particle density
        const scalar rhoP = model_->parameters().rhoP;
        return granairTwoFluid::pointwise
        (
            name, phase, tg(), dimPressure, [&](double c, double g) { return rhoP*law(c, g, cMin); }
        );
    }
    catch (const ::granair::Error& e)
    {
        FatalErrorInFunction << "frictionalStressModel latzSchmidt: " << e.what() << exit(FatalError);
    }
    return tmp<volScalarField>(nullptr);
}


Foam::tmp<Foam::volScalarField> latzSchmidt::frictionalPressure
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    return field
    (
        "latzSchmidt:pf", phase, alphaMinFriction.value(),
        [this](double c, double g, double cMin) { return pressure(c, g, cMin); }
    );
}


Foam::tmp<Foam::volScalarField> latzSchmidt::frictionalPressurePrime
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax
) const
{
    if (granairTwoFluid::secantRequested(phase.mesh()))
    {
        // the face ratio of the frictionalPressureSecant scheme (PressureSecant.H)
        const scalar cMin = alphaMinFriction.value();
        const scalar rhoP = model_->parameters().rhoP;
        const tmp<volScalarField> tg = granairTwoFluid::shearRate(phase.U());
        try
        {
            granairTwoFluid::publishSecantRatio
            (
                phase, tg(),
                [&](double c, double g) { return rhoP*pressure(c, g, cMin); },
                [&](double c, double g) { return rhoP*pressurePrime(c, g, cMin); }
            );
        }
        catch (const ::granair::Error& e)
        {
            FatalErrorInFunction << "frictionalStressModel latzSchmidt: " << e.what() << exit(FatalError);
        }
    }
    return field
    (
        "latzSchmidt:pfPrime", phase, alphaMinFriction.value(),
        [this](double c, double g, double cMin) { return pressurePrime(c, g, cMin); }
    );
}


Foam::tmp<Foam::volScalarField> latzSchmidt::nu
(
    const phaseModel& phase,
    const dimensionedScalar& alphaMinFriction,
    const dimensionedScalar& alphaMax,
    const volScalarField& pf,
    const volSymmTensorField& D
) const
{
    checkPhase(phase);
    const scalar rhoP = model_->parameters().rhoP;
    const tmp<volScalarField> tg = granairTwoFluid::shearRate(D);
    const volScalarField& gammaDot = tg();
    // pf is p_f/rho_p here (kineticTheoryModel divides by the phase density)
    tmp<volScalarField> tnu = granairTwoFluid::pointwise
    (
        "latzSchmidt:nu", pf, gammaDot, dimViscosity,
        [&](double q, double g) { return viscosity(q, g); }
    );
    granairTwoFluid::publish(phase, rhoP, pf, tnu());
    return tnu;
}


bool latzSchmidt::read()
{
    coeffDict_ <<= dict_.optionalSubDict(typeName + "Coeffs");
    readCoeffs();
    return true;
}
