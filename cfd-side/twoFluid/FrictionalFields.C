/*---------------------------------------------------------------------------*\
    granair: see FrictionalFields.H
\*---------------------------------------------------------------------------*/
#include "FrictionalFields.H"

#include "calculatedFvPatchFields.H"
#include "fvcGrad.H"

Foam::tmp<Foam::volScalarField> Foam::granairTwoFluid::shearRate(const Foam::volSymmTensorField& D)
{
    const volSymmTensorField devD(dev(D));
    return sqrt(2.0*(devD && devD));
}


Foam::tmp<Foam::volScalarField> Foam::granairTwoFluid::shearRate(const Foam::volVectorField& U)
{
    return shearRate(volSymmTensorField(symm(fvc::grad(U))));
}


void Foam::granairTwoFluid::publish
(
    const Foam::phaseModel& phase,
    const Foam::scalar rhoP,
    const Foam::volScalarField& pfOverRho,
    const Foam::volScalarField& nuf
)
{
    using namespace Foam;
    const fvMesh& mesh = phase.mesh();
    const word pName(IOobject::groupName("pf", phase.name()));
    const word muName(IOobject::groupName("muFriction", phase.name()));
    for (const word& name : {pName, muName})
    {
        if (!mesh.foundObject<volScalarField>(name))
        {
            const dimensionSet dims = name == pName ? dimPressure : dimPressure*dimTime;
            mesh.objectRegistry::store
            (
                new volScalarField
                (
                    IOobject(name, mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                    mesh,
                    dimensionedScalar(dims, Zero),
                    calculatedFvPatchScalarField::typeName
                )
            );
        }
    }
    volScalarField& pfField = mesh.lookupObjectRef<volScalarField>(pName);
    volScalarField& muField = mesh.lookupObjectRef<volScalarField>(muName);
    pfField.primitiveFieldRef() = rhoP*pfOverRho.primitiveField();
    muField.primitiveFieldRef() = rhoP*nuf.primitiveField();
    forAll(pfField.boundaryField(), patchi)
    {
        pfField.boundaryFieldRef()[patchi] == rhoP*pfOverRho.boundaryField()[patchi];
        muField.boundaryFieldRef()[patchi] == rhoP*nuf.boundaryField()[patchi];
    }
}


bool Foam::granairTwoFluid::secantRequested(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const dictionary* schemes = mesh.schemesDict().findDict("interpolationSchemes");
    if (!schemes) return false;
    for (const entry& e : *schemes)
    {
        if (e.isStream())
        {
            const ITstream& is = e.stream();
            if (is.size() && is[0].isWord() && is[0].wordToken() == "frictionalPressureSecant") return true;
        }
    }
    return false;
}


Foam::surfaceScalarField& Foam::granairTwoFluid::secantRatioField(const Foam::phaseModel& phase)
{
    using namespace Foam;
    const fvMesh& mesh = phase.mesh();
    const word name(IOobject::groupName("pfSecantRatio", phase.name()));
    if (!mesh.foundObject<surfaceScalarField>(name))
    {
        mesh.objectRegistry::store
        (
            new surfaceScalarField
            (
                IOobject(name, mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
                mesh,
                dimensionedScalar("one", dimless, 1.0)
            )
        );
    }
    return mesh.lookupObjectRef<surfaceScalarField>(name);
}
