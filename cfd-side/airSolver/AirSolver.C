/*---------------------------------------------------------------------------*\
    granair: AirSolver (see AirSolver.H for the equations)
\*---------------------------------------------------------------------------*/
#include "airSolver/AirSolver.H"

#include "constrainHbyA.H"
#include "findRefCell.H"
#include "reverseLinear.H"

namespace Foam
{
namespace granair
{

AirSolver::AirSolver(fvMesh& mesh)
:
    mesh_(mesh),
    transportProperties_
    (
        IOobject
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    rho_("rho", dimDensity, transportProperties_),
    mu_("mu", dimDynamicViscosity, transportProperties_),
    pimple_(mesh),
    U_
    (
        IOobject("U", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    p_
    (
        IOobject("p", mesh.time().timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    ),
    voidfraction_
    (
        IOobject
        (
            "voidfraction", mesh.time().timeName(), mesh,
            IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        "zeroGradient"
    ),
    Ksl_
    (
        IOobject("Ksl", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedScalar("zero", dimDensity/dimTime, 0.0),
        "zeroGradient"
    ),
    Us_
    (
        IOobject("Us", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedVector("zero", dimVelocity, Zero),
        "zeroGradient"
    ),
    phi_
    (
        IOobject
        (
            "phi", mesh.time().timeName(), mesh,
            IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE
        ),
        fvc::flux(U_)
    ),
    pf_("pFace", fvc::interpolate(p_)),
    gradP_
    (
        IOobject("gradP", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        fvc::grad(p_)
    ),
    pRefCell_(0),
    pRefValue_(0),
    cumulativeContErr_(0),
    lastContErr_(0)
{
    if (rho_.value() <= 0 || mu_.value() <= 0)
    {
        FatalIOErrorInFunction(transportProperties_)
            << "rho and mu must be positive, found rho " << rho_.value()
            << " kg/m3, mu " << mu_.value() << " Pa s" << exit(FatalIOError);
    }
    setRefCell(p_, pimple_.dict(), pRefCell_, pRefValue_);
    mesh_.setFluxRequired(p_.name());
    checkVoidFraction();
    // Make the old-time level exist before the caller first changes eps,
    // so d(eps)/dt of the first step is (eps_new - eps_initial)/dt.
    voidfraction_.oldTime();
    // The face time coupling uses the previous step's flux.
    phi_.oldTime();
}


void AirSolver::checkVoidFraction() const
{
    const scalarField& eps = voidfraction_.primitiveField();
    forAll(eps, celli)
    {
        const scalar e = eps[celli];
        if (!(e > 0 && e <= 1))
        {
            FatalErrorInFunction
                << "void fraction " << e << " in cell " << celli
                << " at " << mesh_.C()[celli];
            if (Pstream::parRun())
            {
                FatalError<< " (processor " << Pstream::myProcNo() << ")";
            }
            FatalError<< ": expected 0 < voidfraction <= 1" << exit(FatalError);
        }
    }
}


void AirSolver::solveStep()
{
    checkVoidFraction();
    volScalarField& eps = voidfraction_;
    volVectorField& U = U_;
    volScalarField& p = p_;
    surfaceScalarField& phi = phi_;
    const dimensionedScalar& rho = rho_;
    const volScalarField KbyRho("KbyRho", Ksl_/rho);
    const surfaceVectorField& Sf = mesh_.Sf();

    // Means along the line between two cell centres, each cell's value over
    // its own part of the line: the owner's share is 1 - w, the neighbour's
    // w (w the linear weight), i.e. OpenFOAM's reverseLinear weights.
    const reverseLinear<scalar> lineMeanS(mesh_);
    const reverseLinear<vector> lineMeanV(mesh_);

    // Inertia per unit superficial velocity on the line: mean of 1/eps.
    const surfaceScalarField mf("mf", lineMeanS.interpolate(1.0/eps));

    // Old superficial face flux: phi is stored per interstitial velocity,
    // with the linear face eps of its own step.
    const surfaceScalarField phiSupOld
    (
        "phiSupOld", fvc::interpolate(eps.oldTime())*phi.oldTime()
    );

    while (pimple_.loop())
    {
        const surfaceScalarField epsf("epsf", fvc::interpolate(eps));
        const surfaceScalarField epsPhi("epsPhi", epsf*phi);
        const volScalarField epsNu("epsNu", eps*(mu_/rho_));

        // Non-conservative form: eps (dU/dt + U.grad U), consistent with
        // continuity, as in cfdemSolverPiso and DPMFoam.
        fvVectorMatrix UEqn
        (
            fvm::ddt(eps, U)
          + fvm::div(epsPhi, U)
          - fvm::Sp(fvc::ddt(eps) + fvc::div(epsPhi), U)
          - fvm::laplacian(epsNu, U)
          - fvc::div(epsNu*dev2(T(fvc::grad(U))))
          + fvm::Sp(KbyRho, U)
        );
        UEqn.relax();

        if (pimple_.momentumPredictor())
        {
            // gradP_ is the face-consistent gradient of the current p.
            solve(UEqn == KbyRho*Us_ - eps*gradP_/rho);
        }

        while (pimple_.correct())
        {
            const volScalarField A("A", UEqn.A());

            // H/A including the implicit-drag pull towards the particle velocity.
            volVectorField HbyA
            (
                constrainHbyA((UEqn.H() + KbyRho*Us_)/A, U, p)
            );

            // Superficial form of the cell balance, a u = h - grad(p)/rho
            // (u = eps U): resistance a and pseudo-velocity uTilde = h/a.
            const volScalarField a("a", A/sqr(eps));
            const volVectorField uTilde("uTilde", eps*HbyA);
            const surfaceScalarField af("af", lineMeanS.interpolate(a));

            // Time coupling (ddtCorr): the old-time part of h_f uses the old
            // face flux instead of the line mean of the old cell velocities.
            // Coefficient as fvc::ddtCorr (OpenFOAM v1712 form), zero on
            // boundaries where U is fixed.
            const volVectorField uOldByEps("uOldByEps", eps.oldTime()*U.oldTime()/eps);
            const surfaceScalarField phiCorr
            (
                "phiCorr", phiSupOld - (lineMeanV.interpolate(uOldByEps) & Sf)/mf
            );
            surfaceScalarField ddtCoeff
            (
                "ddtCoeff",
                1.0
              - min
                (
                    mag(phiCorr)
                   /(mag(phiSupOld) + dimensionedScalar("small", phiSupOld.dimensions(), SMALL)),
                    scalar(1)
                )
            );
            forAll(U.boundaryField(), patchi)
            {
                if (U.boundaryField()[patchi].fixesValue())
                {
                    ddtCoeff.boundaryFieldRef()[patchi] = 0;
                }
            }
            // c_f |S|, the time coupling in the units of h . S [m3/s2].
            const surfaceScalarField ddtFlux
            (
                "ddtFlux", ddtCoeff*mf*phiCorr/mesh_.time().deltaT()
            );

            // Predicted superficial face flux [m3/s].
            surfaceScalarField phiHbyA
            (
                "phiHbyA",
                ((lineMeanV.interpolate(a*uTilde) & Sf) + ddtFlux)/af
            );
            if (p.needReference())
            {
                adjustPhi(phiHbyA, U, p);
            }

            while (pimple_.correctNonOrthogonal())
            {
                fvScalarMatrix pEqn
                (
                    fvm::laplacian(1.0/(rho*af), p)
                 ==
                    fvc::ddt(eps) + fvc::div(phiHbyA)
                );
                pEqn.setReference(pRefCell_, pRefValue_);
                pEqn.solve(mesh_.solver(p.select(pimple_.finalInnerIter())));

                if (pimple_.finalNonOrthogonalIter())
                {
                    phi = (phiHbyA - pEqn.flux())/epsf;
                }
            }

            updateFacePressure(a, uTilde, ddtFlux/mesh_.magSf());
            U = HbyA - eps*gradP_/(rho*A);
            U.correctBoundaryConditions();

            // Continuity error of the volume-averaged equation.
            const volScalarField contErr(fvc::ddt(eps) + fvc::div(epsf*phi));
            lastContErr_ =
                mesh_.time().deltaTValue()*mag(contErr)().weightedAverage(mesh_.V()).value();
            cumulativeContErr_ +=
                mesh_.time().deltaTValue()*contErr.weightedAverage(mesh_.V()).value();
        }
    }
}


void AirSolver::updateFacePressure
(
    const volScalarField& a,
    const volVectorField& uTilde,
    const surfaceScalarField& c
)
{
    const scalar rho = rho_.value();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& deltaCoeffs = mesh_.nonOrthDeltaCoeffs();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();

    // The face balance split at the face: owner side over (1-w) d, neighbour
    // side over w d; p_f eliminates the face flux between the two halves.
    auto facePressure = [rho]
    (
        scalar wf, scalar d, scalar aP, scalar aN, scalar pP, scalar pN,
        scalar hP, scalar hN
    )
    {
        return
        (
            wf*aN*pP + (1 - wf)*aP*pN + rho*(1 - wf)*wf*d*(aN*hP - aP*hN)
        )/((1 - wf)*aP + wf*aN);
    };

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& aI = a.primitiveField();
    const vectorField& uI = uTilde.primitiveField();
    const scalarField& pI = p_.primitiveField();
    scalarField& pfI = pf_.primitiveFieldRef();
    forAll(own, facei)
    {
        const label P = own[facei];
        const label N = nei[facei];
        const vector n = Sf[facei]/magSf[facei];
        pfI[facei] = facePressure
        (
            w[facei], 1.0/deltaCoeffs[facei], aI[P], aI[N], pI[P], pI[N],
            aI[P]*(uI[P] & n) + c[facei], aI[N]*(uI[N] & n) + c[facei]
        );
    }

    surfaceScalarField::Boundary& pfB = pf_.boundaryFieldRef();
    forAll(pfB, patchi)
    {
        const fvPatchScalarField& pB = p_.boundaryField()[patchi];
        if (!pB.coupled())
        {
            pfB[patchi] = pB;
            if (U_.boundaryField()[patchi].fixesValue() && !pB.fixesValue())
            {
                // The flux is set by U here (an inlet, a distributor, a
                // wall) and p is not fixed (zero-gradient): the face pressure is
                // the one the cell's own half line needs to pass that
                // flux, p_b = p_P + rho d (h_P.n + c - a_P u_b) (n out of
                // the domain), as fixedFluxPressure would give. With p_P a
                // bed resting on the patch would lose half its first cell
                // of pressure gradient, and that cell half its velocity.
                const labelUList& cells = mesh_.boundary()[patchi].faceCells();
                const scalarField& epsB = voidfraction_.boundaryField()[patchi];
                const scalarField& phiB = phi_.boundaryField()[patchi];
                const scalarField& dcB = deltaCoeffs.boundaryField()[patchi];
                const vectorField& SfB = Sf.boundaryField()[patchi];
                const scalarField& magSfB = magSf.boundaryField()[patchi];
                const scalarField& cB = c.boundaryField()[patchi];
                forAll(pfB[patchi], facei)
                {
                    const label P = cells[facei];
                    const scalar uB = epsB[facei]*phiB[facei]/magSfB[facei];
                    const scalar hP = aI[P]*(uI[P] & SfB[facei])/magSfB[facei];
                    pfB[patchi][facei] =
                        pI[P] + rho/dcB[facei]*(hP + cB[facei] - aI[P]*uB);
                }
            }
            continue;
        }
        const scalarField aP(a.boundaryField()[patchi].patchInternalField());
        const scalarField aN(a.boundaryField()[patchi].patchNeighbourField());
        const vectorField uP(uTilde.boundaryField()[patchi].patchInternalField());
        const vectorField uN(uTilde.boundaryField()[patchi].patchNeighbourField());
        const scalarField pP(pB.patchInternalField());
        const scalarField pN(pB.patchNeighbourField());
        const scalarField& wB = w.boundaryField()[patchi];
        const scalarField& dcB = deltaCoeffs.boundaryField()[patchi];
        const vectorField nB(Sf.boundaryField()[patchi]/magSf.boundaryField()[patchi]);
        const scalarField& cB = c.boundaryField()[patchi];
        forAll(pfB[patchi], facei)
        {
            pfB[patchi][facei] = facePressure
            (
                wB[facei], 1.0/dcB[facei], aP[facei], aN[facei], pP[facei], pN[facei],
                aP[facei]*(uP[facei] & nB[facei]) + cB[facei],
                aN[facei]*(uN[facei] & nB[facei]) + cB[facei]
            );
        }
    }

    gradP_ = fvc::surfaceIntegrate(Sf*pf_);
    gradP_.correctBoundaryConditions();
}


scalar AirSolver::airMass() const
{
    return gSum(rho_.value()*voidfraction_.primitiveField()*mesh_.V().field());
}

} // namespace granair
} // namespace Foam
