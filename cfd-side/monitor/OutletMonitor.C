/*---------------------------------------------------------------------------*\
    granair: OutletMonitor (see OutletMonitor.H)
\*---------------------------------------------------------------------------*/
#include "monitor/OutletMonitor.H"

#include "processorPolyPatch.H"
#include "core/Error.hpp"

namespace Foam
{
namespace granair
{

static vector toVector(const ::granair::Vec3& v)
{
    return vector(v.x(), v.y(), v.z());
}

OutletMonitor::OutletMonitor(const fvMesh& mesh, const ::granair::Dictionary& dict)
:
    mesh_(mesh)
{
    n_ = toVector(dict.getVec3("normal"));
    if (mag(n_) < SMALL)
    {
        ::granair::fail<::granair::InputError>(dict.where("normal"), ": expected a non-zero vector");
    }
    n_ /= mag(n_);
    const std::string type = dict.getString("type");
    DynamicList<label> iFaces;
    DynamicList<scalar> iSign;
    DynamicList<labelPair> bFaces;
    DynamicList<scalar> bSign;

    if (type == "patch")
    {
        const std::string name = dict.getString("patch");
        const label patchi = mesh.boundaryMesh().findPatchID(word(name));
        if (patchi < 0)
        {
            ::granair::fail<::granair::InputError>
            (
                dict.where("patch"), ": no boundary patch '", name, "' in the mesh"
            );
        }
        const fvPatch& pp = mesh.boundary()[patchi];
        forAll(pp, facei)
        {
            bFaces.append(labelPair(patchi, facei));
            bSign.append(sign(pp.Sf()[facei] & n_));
        }
    }
    else if (type == "plane")
    {
        const point p0 = toVector(dict.getVec3("point"));
        const point lo = toVector(dict.getVec3("boxMin"));
        const point hi = toVector(dict.getVec3("boxMax"));
        const boundBox box(lo, hi);
        const surfaceVectorField& Cf = mesh.Cf();
        const surfaceVectorField& Sf = mesh.Sf();
        const surfaceScalarField& magSf = mesh.magSf();
        // A face is on the plane when its centre is within a small fraction
        // of its own size from it and it is parallel to it.
        auto onPlane = [&](const point& c, const vector& s, scalar a)
        {
            return mag((c - p0) & n_) < 1e-6*Foam::sqrt(a)
                && mag(s & n_) > 0.999*a && box.contains(c);
        };
        for (label facei = 0; facei < mesh.nInternalFaces(); ++facei)
        {
            if (onPlane(Cf[facei], Sf[facei], magSf[facei]))
            {
                iFaces.append(facei);
                iSign.append(sign(Sf[facei] & n_));
            }
        }
        forAll(mesh.boundaryMesh(), patchi)
        {
            const polyPatch& pp = mesh.boundaryMesh()[patchi];
            const auto* proc = isA<processorPolyPatch>(pp);
            // Only coupled processor faces can lie inside the fluid; count
            // each once, on the lower rank.
            if (!proc || proc->myProcNo() > proc->neighbProcNo())
            {
                continue;
            }
            forAll(pp, facei)
            {
                if (onPlane(Cf.boundaryField()[patchi][facei], Sf.boundaryField()[patchi][facei],
                            magSf.boundaryField()[patchi][facei]))
                {
                    bFaces.append(labelPair(patchi, facei));
                    bSign.append(sign(Sf.boundaryField()[patchi][facei] & n_));
                }
            }
        }
    }
    else
    {
        ::granair::fail<::granair::InputError>
        (
            dict.where("type"), ": unknown outlet type '", type, "', expected 'patch' or 'plane'"
        );
    }
    internalFaces_.transfer(iFaces);
    internalSign_.transfer(iSign);
    boundaryFaces_.transfer(bFaces);
    boundarySign_.transfer(bSign);

    if (totalArea() <= 0)
    {
        ::granair::fail<::granair::InputError>
        (
            dict.where("type"), ": the outlet selects no faces (check point/normal/box: the plane "
            "must coincide with mesh faces)"
        );
    }
}


scalar OutletMonitor::totalArea() const
{
    scalar a = 0;
    forAll(internalFaces_, i)
    {
        a += mesh_.magSf()[internalFaces_[i]];
    }
    forAll(boundaryFaces_, i)
    {
        a += mesh_.magSf().boundaryField()[boundaryFaces_[i].first()][boundaryFaces_[i].second()];
    }
    return returnReduce(a, sumOp<scalar>());
}


OutletValues OutletMonitor::evaluate
(
    const volScalarField& p,
    const surfaceScalarField& pFace,
    const surfaceScalarField& phi,
    const volScalarField& eps,
    scalar rho
) const
{
    const surfaceScalarField snGradP(fvc::snGrad(p));
    const surfaceScalarField& pf = pFace;
    const surfaceScalarField epsf(fvc::interpolate(eps));
    const surfaceScalarField& magSf = mesh_.magSf();

    scalar sumA = 0, sumG = 0, sumP = 0, sumM = 0;
    forAll(internalFaces_, i)
    {
        const label f = internalFaces_[i];
        const scalar a = magSf[f];
        sumA += a;
        sumG += internalSign_[i]*snGradP[f]*a;
        sumP += pf[f]*a;
        sumM += internalSign_[i]*rho*epsf[f]*phi[f];
    }
    forAll(boundaryFaces_, i)
    {
        const label pi = boundaryFaces_[i].first();
        const label f = boundaryFaces_[i].second();
        const scalar a = magSf.boundaryField()[pi][f];
        sumA += a;
        sumG += boundarySign_[i]*snGradP.boundaryField()[pi][f]*a;
        sumP += pf.boundaryField()[pi][f]*a;
        sumM += boundarySign_[i]*rho*epsf.boundaryField()[pi][f]*phi.boundaryField()[pi][f];
    }
    reduce(sumA, sumOp<scalar>());
    reduce(sumG, sumOp<scalar>());
    reduce(sumP, sumOp<scalar>());
    reduce(sumM, sumOp<scalar>());

    OutletValues v;
    v.area = sumA;
    v.dpdn = sumA > 0 ? sumG/sumA : 0;
    v.pMean = sumA > 0 ? sumP/sumA : 0;
    v.massFlux = sumM;
    return v;
}

} // namespace granair
} // namespace Foam
