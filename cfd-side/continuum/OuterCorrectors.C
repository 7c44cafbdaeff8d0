/*---------------------------------------------------------------------------*\
    granair: OuterCorrectors (see OuterCorrectors.H)
\*---------------------------------------------------------------------------*/
#include "OuterCorrectors.H"

namespace Foam
{
namespace granair
{

namespace
{

label positiveLabel(const dictionary& d, const word& key, label fallback, label least)
{
    const label v = d.lookupOrDefault<label>(key, fallback);
    if (v < least)
    {
        FatalIOErrorInFunction(d)
            << "PIMPLE " << key << " = " << v << ", expected an integer >= " << least << exit(FatalIOError);
    }
    return v;
}

} // namespace

OuterCorrectors::OuterCorrectors(const fvMesh& mesh)
:
    nOuter(0),
    nCorr(0),
    nNonOrth(0),
    momentumPredictor(true),
    inertialProjection(true),
    transposeStress(true),
    tolerance(0),
    dict_(mesh.solutionDict().subDict("PIMPLE"))
{
    nOuter = positiveLabel(dict_, "nOuterCorrectors", 1, 1);
    nCorr = positiveLabel(dict_, "nCorrectors", 3, 1);
    nNonOrth = positiveLabel(dict_, "nNonOrthogonalCorrectors", 0, 0);
    momentumPredictor = dict_.lookupOrDefault<Switch>("momentumPredictor", true);
    const word correction = dict_.lookupOrDefault<word>("pressureCorrection", "inertial");
    if (correction != "inertial" && correction != "piso")
    {
        FatalIOErrorInFunction(dict_)
            << "PIMPLE pressureCorrection " << correction << ", expected inertial or piso" << exit(FatalIOError);
    }
    inertialProjection = correction == "inertial";
    if (dict_.found("consistent"))
    {
        FatalIOErrorInFunction(dict_)
            << "PIMPLE consistent: not used by granairContinuumFoam (SIMPLEC diverges next to walls where "
            << "viscosity dominates); use pressureCorrection inertial or piso (OuterCorrectors.H)"
            << exit(FatalIOError);
    }
    transposeStress = dict_.lookupOrDefault<Switch>("transposeStress", true);
    tolerance = dict_.lookupOrDefault<scalar>("outerTolerance", 1e-3);
    if (!(tolerance > 0 && tolerance < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "PIMPLE outerTolerance = " << tolerance
            << ", expected 0 < outerTolerance < 1 (relative change of U and p per outer corrector)"
            << exit(FatalIOError);
    }
    Info<< "Outer correctors: " << nOuter << " per step";
    if (nOuter > 1)
    {
        Info<< " at most, converged when U and p change by less than " << tolerance << " (relative)";
    }
    Info<< ", " << nCorr << " pressure correctors, " << (inertialProjection ? "inertial" : "PISO")
        << " pressure correction, transpose stress " << (transposeStress ? "on" : "off") << nl << endl;
}

OuterCorrectors::Residual OuterCorrectors::residual
(
    const volVectorField& U,
    const volVectorField& U0,
    const volScalarField& p,
    const volScalarField& p0,
    const volScalarField& alpha
)
{
    const scalarField powder(pos0(alpha.primitiveField() - 0.5));
    const scalarField changeU(powder*mag(U.primitiveField() - U0.primitiveField()));
    const scalarField changeP(powder*mag(p.primitiveField() - p0.primitiveField()));
    const scalar dU = gMax(changeU);
    const scalar dp = gMax(changeP);
    const scalar uScale = max(gMax(powder*mag(U.primitiveField())), scalar(1e-4));
    const scalar pScale = max(gMax(powder*mag(p.primitiveField())), scalar(1));
    const vectorField& C = U.mesh().C().primitiveField();
    const point whereU = changeU.size() ? C[findMax(changeU)] : point::zero;
    const point whereP = changeP.size() ? C[findMax(changeP)] : point::zero;
    return {dU/uScale, dp/pScale, whereU, whereP};
}

} // namespace granair
} // namespace Foam
