/*---------------------------------------------------------------------------*\
    granair: AlphaAdvection (see AlphaAdvection.H)
\*---------------------------------------------------------------------------*/
#include "AlphaAdvection.H"

#include "MULES.H"

namespace Foam
{
namespace granair
{

namespace
{

// Unit interface normal dotted with the face area vectors [m2].
tmp<surfaceScalarField> interfaceNormalFlux(const volScalarField& alpha)
{
    const fvMesh& mesh = alpha.mesh();
    // Stabilisation for |grad alpha| -> 0 (the value interfaceProperties uses).
    const dimensionedScalar deltaN
    (
        "deltaN", dimless/dimLength, 1e-8/pow(average(mesh.V()), 1.0/3.0).value()
    );
    const surfaceVectorField gradAlphaf(fvc::interpolate(fvc::grad(alpha)));
    return (gradAlphaf/(mag(gradAlphaf) + deltaN)) & mesh.Sf();
}

// One to nAlphaCorr MULES passes with the source Su (zeroField: none).
template<class SuType>
void advect(volScalarField& alpha, const surfaceScalarField& phi, surfaceScalarField& alphaPhi, const SuType& Su)
{
    const fvMesh& mesh = alpha.mesh();
    const dictionary& controls = mesh.solverDict(alpha.name());
    const label nAlphaCorr = controls.lookupOrDefault<label>("nAlphaCorr", 1);
    const scalar cAlpha = controls.lookupOrDefault<scalar>("cAlpha", 1.0);

    // Compression velocity magnitude on faces; none through non-coupled
    // boundaries (walls, outlet, atmosphere).
    surfaceScalarField phic(cAlpha*mag(phi/mesh.magSf()));
    surfaceScalarField::Boundary& phicBf = phic.boundaryFieldRef();
    forAll(phicBf, patchi)
    {
        if (!phicBf[patchi].coupled())
        {
            phicBf[patchi] == 0;
        }
    }

    for (label corr = 0; corr < nAlphaCorr; ++corr)
    {
        const surfaceScalarField phir(phic*interfaceNormalFlux(alpha));
        alphaPhi =
            fvc::flux(phi, alpha, "div(phi,alpha)")
          + fvc::flux(-fvc::flux(-phir, scalar(1) - alpha, "div(phirb,alpha)"), alpha, "div(phirb,alpha)");

        MULES::explicitSolve(geometricOneField(), alpha, phi, alphaPhi, zeroField(), Su, oneField(), zeroField());
    }
}

} // namespace

void advectAlpha(volScalarField& alpha, const surfaceScalarField& phi, surfaceScalarField& alphaPhi)
{
    advect(alpha, phi, alphaPhi, zeroField());
}

void advectAlphaDilatant(volScalarField& alpha, const surfaceScalarField& phi, surfaceScalarField& alphaPhi)
{
    // Only where there is powder: in the air div(phi) is the pressure solver's
    // residual, which as a source would make (and then move out) spurious powder.
    const volScalarField::Internal divU
    (
        "divU", fvc::div(phi)().internalField()*pos(alpha.internalField() - 1e-6)
    );
    advect(alpha, phi, alphaPhi, divU);
}

} // namespace granair
} // namespace Foam
