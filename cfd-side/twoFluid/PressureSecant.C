/*---------------------------------------------------------------------------*\
    granair: see PressureSecant.H
\*---------------------------------------------------------------------------*/
#include "PressureSecant.H"

namespace Foam
{
    defineTypeNameAndDebug(frictionalPressureSecant, 0);
    surfaceInterpolationScheme<scalar>::addMeshConstructorToTable<frictionalPressureSecant>
        addFrictionalPressureSecantMeshConstructorToTable_;
    surfaceInterpolationScheme<scalar>::addMeshFluxConstructorToTable<frictionalPressureSecant>
        addFrictionalPressureSecantMeshFluxConstructorToTable_;
}


void Foam::frictionalPressureSecant::readName(Istream& is)
{
    if (is.eof())
    {
        FatalIOErrorInFunction(is)
            << "fvSchemes: frictionalPressureSecant expects the name of the frictional model's face ratio,"
            << " e.g. frictionalPressureSecant pfSecantRatio.particles" << exit(FatalIOError);
    }
    is >> ratioName_;
}


Foam::frictionalPressureSecant::frictionalPressureSecant(const fvMesh& mesh, Istream& is)
:
    surfaceInterpolationScheme<scalar>(mesh)
{
    readName(is);
}


Foam::frictionalPressureSecant::frictionalPressureSecant
(
    const fvMesh& mesh,
    const surfaceScalarField&,
    Istream& is
)
:
    surfaceInterpolationScheme<scalar>(mesh)
{
    readName(is);
}


Foam::tmp<Foam::surfaceScalarField> Foam::frictionalPressureSecant::weights(const volScalarField&) const
{
    return this->mesh().surfaceInterpolation::weights();
}


Foam::tmp<Foam::surfaceScalarField>
Foam::frictionalPressureSecant::correction(const volScalarField& vf) const
{
    const fvMesh& mesh = this->mesh();
    if (!mesh.foundObject<surfaceScalarField>(ratioName_))
    {
        FatalErrorInFunction
            << "fvSchemes: frictionalPressureSecant (interpolating " << vf.name() << ") needs the face field '"
            << ratioName_ << "', not registered: the frictionalStressModels muI and latzSchmidt publish"
            << " pfSecantRatio.<phase> (kineticTheoryCoeffs frictionalStressModel)" << exit(FatalError);
    }
    const surfaceScalarField& ratio = mesh.lookupObject<surfaceScalarField>(ratioName_);
    if (debug)
    {
        Info<< "frictionalPressureSecant: " << ratioName_ << " min " << min(ratio).value() << " max "
            << max(ratio).value() << endl;
    }
    // linear + correction = ratio x linear
    return (ratio - 1)*surfaceInterpolationScheme<scalar>::interpolate(vf, mesh.surfaceInterpolation::weights());
}
