/*---------------------------------------------------------------------------*\
    granair: Reconstruct (see Reconstruct.H)
\*---------------------------------------------------------------------------*/
#include "Reconstruct.H"

#include "extrapolatedCalculatedFvPatchFields.H"

namespace Foam
{
namespace granair
{

tmp<volVectorField> reconstructVector(const surfaceScalarField& ssf)
{
    const fvMesh& mesh = ssf.mesh();
    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    const vectorField& Sf = mesh.Sf().primitiveField();
    const scalarField& magSf = mesh.magSf().primitiveField();

    tensorField T(mesh.nCells(), Zero);
    vectorField S(mesh.nCells(), Zero);
    forAll(owner, facei)
    {
        const vector n = Sf[facei]/magSf[facei];
        const tensor nn = n*Sf[facei];
        const vector nF = n*ssf[facei];
        T[owner[facei]] += nn;
        T[neighbour[facei]] += nn;
        S[owner[facei]] += nF;
        S[neighbour[facei]] += nF;
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const labelUList& cells = patch.faceCells();
        const vectorField& pSf = patch.Sf();
        const scalarField& pMagSf = patch.magSf();
        const fvsPatchScalarField& pF = ssf.boundaryField()[patchi];
        forAll(cells, facei)
        {
            const vector n = pSf[facei]/pMagSf[facei];
            T[cells[facei]] += n*pSf[facei];
            S[cells[facei]] += n*pF[facei];
        }
    }

    auto tresult = tmp<volVectorField>::New
    (
        IOobject("reconstruct(" + ssf.name() + ')', mesh.time().timeName(), mesh),
        mesh,
        dimensioned<vector>(ssf.dimensions()/dimArea, Zero),
        extrapolatedCalculatedFvPatchField<vector>::typeName
    );
    vectorField& result = tresult.ref().primitiveFieldRef();
    // inv() of the whole field drops directions a 2-D mesh has no faces in
    // (empty patches); do the same per cell.
    const tensorField Tinv(inv(T));
    forAll(result, celli)
    {
        result[celli] = Tinv[celli] & S[celli];
    }
    tresult.ref().correctBoundaryConditions();
    return tresult;
}

} // namespace granair
} // namespace Foam
