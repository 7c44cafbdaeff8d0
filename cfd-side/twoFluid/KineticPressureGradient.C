/*---------------------------------------------------------------------------*\
    granair: fv::kineticPressureGradient (see KineticPressureGradient.H)
\*---------------------------------------------------------------------------*/
#include "KineticPressureGradient.H"

#include "IOdictionary.H"
#include "addToRunTimeSelectionTable.H"
#include "fvcGrad.H"
#include "fvcReconstruct.H"
#include "fvcSnGrad.H"
#include "fvMatrices.H"
#include "surfaceInterpolate.H"

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(kineticPressureGradient, 0);
    addToRunTimeSelectionTable(option, kineticPressureGradient, dictionary);
}
}


Foam::fv::kineticPressureGradient::kineticPressureGradient
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh)
{
    read(dict);
}


bool Foam::fv::kineticPressureGradient::read(const dictionary& dict)
{
    if (!option::read(dict)) return false;
    if (!coeffs_.readIfPresent("phase", phaseName_))
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOption " << name_ << " (kineticPressureGradient): missing key 'phase' "
            << "(the particle phase, e.g. particles)" << exit(FatalIOError);
    }
    fieldNames_ = wordList(1, IOobject::groupName("U", phaseName_));
    applied_.setSize(1, false);
    constantsRead_ = false;
    return true;
}


void Foam::fv::kineticPressureGradient::readConstants()
{
    if (constantsRead_) return;
    const word dictName(IOobject::groupName("turbulenceProperties", phaseName_));
    if (!mesh_.foundObject<IOdictionary>(dictName))
    {
        FatalErrorInFunction
            << "fvOption " << name_ << ": no " << dictName << " (phase '" << phaseName_
            << "' needs the kineticTheory RAS model)" << exit(FatalError);
    }
    const dictionary& ras = mesh_.lookupObject<IOdictionary>(dictName).subDict("RAS");
    const dictionary& kt = ras.subDict("kineticTheoryCoeffs");
    const word pressure(kt.get<word>("granularPressureModel"));
    const word radial(kt.get<word>("radialModel"));
    if (ras.get<word>("RASModel") != "kineticTheory" || pressure != "Lun" || radial != "SinclairJackson")
    {
        FatalIOErrorInFunction(kt)
            << "fvOption " << name_ << " (kineticPressureGradient): expected RASModel kineticTheory with "
            << "granularPressureModel Lun and radialModel SinclairJackson in " << dictName
            << ", got " << ras.get<word>("RASModel") << ", " << pressure << ", " << radial
            << exit(FatalIOError);
    }
    e_ = kt.get<scalar>("e");
    alphaMax_ = kt.get<scalar>("alphaMax");
    alphaMinFriction_ = kt.get<scalar>("alphaMinFriction");
    constantsRead_ = true;
}


void Foam::fv::kineticPressureGradient::addSup
(
    const volScalarField& alpha,
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    readConstants();
    const volScalarField& Theta =
        mesh_.lookupObject<volScalarField>(IOobject::groupName("Theta", phaseName_));

    // Lun et al.'s kinetic pressure with the Sinclair-Jackson g0 and its
    // alpha-derivative, as kineticTheoryModels (g0 frozen above
    // alphaMinFriction; g0' evaluated from alpha >= 1e-3).
    const volScalarField aFric(min(alpha, alphaMinFriction_));
    const volScalarField g0(1.0/(1.0 - cbrt(aFric/alphaMax_)));
    const volScalarField s(cbrt(max(aFric, scalar(1e-3))/alphaMax_));
    const volScalarField g0prime((1.0/(3*alphaMax_))/sqr(s - sqr(s)));
    const volScalarField pk(Theta*rho*alpha*(1.0 + 2*(1 + e_)*alpha*g0));
    volScalarField pkPrime(Theta*rho*(1.0 + alpha*(1 + e_)*(4*g0 + 2*g0prime*alpha)));
    // The solver's part is zero on walls (kineticTheoryModel::pPrime).
    forAll(pkPrime.boundaryField(), patchi)
    {
        if (!pkPrime.boundaryField()[patchi].coupled())
        {
            pkPrime.boundaryFieldRef()[patchi] == 0;
        }
    }
    const surfaceScalarField solverPart
    (
        fvc::interpolate(pkPrime)*fvc::snGrad(alpha)*mesh_.magSf()
    );
    // Only the kinetic part: the frictional (contact) pressure is far too
    // stiff for an explicit source (tried: the bed blew up within 0.1 s), and
    // it is a function of alpha alone, so the solver's pPrime grad(alpha) is
    // already its gradient up to the face interpolation of pPrime.
    const volVectorField S(fvc::reconstruct(solverPart) - fvc::grad(pk));
    if (debug)
    {
        Info<< "kineticPressureGradient: max |S| " << gMax(mag(S)().primitiveField())
            << " max Theta " << gMax(Theta.primitiveField()) << " max pk " << gMax(pk.primitiveField()) << endl;
    }
    eqn += S;
}
