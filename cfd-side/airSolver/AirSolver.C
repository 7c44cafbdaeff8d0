/*---------------------------------------------------------------------------*\
    granair: AirSolver (see AirSolver.H for the equations)
\*---------------------------------------------------------------------------*/
#include "airSolver/AirSolver.H"

#include "constrainHbyA.H"
#include "findRefCell.H"

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
            solve(UEqn == KbyRho*Us_ - eps*fvc::grad(p)/rho);
        }

        while (pimple_.correct())
        {
            const volScalarField rAU("rAU", 1.0/UEqn.A());
            const surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));

            // H/A including the implicit-drag pull towards the particle velocity.
            volVectorField HbyA
            (
                constrainHbyA(rAU*(UEqn.H() + KbyRho*Us_), U, p)
            );
            surfaceScalarField phiHbyA
            (
                "phiHbyA",
                fvc::flux(HbyA) + epsf*rAUf*fvc::ddtCorr(U, phi)
            );
            if (p.needReference())
            {
                adjustPhi(phiHbyA, U, p);
            }

            while (pimple_.correctNonOrthogonal())
            {
                fvScalarMatrix pEqn
                (
                    fvm::laplacian(sqr(epsf)*rAUf/rho, p)
                 ==
                    fvc::ddt(eps) + fvc::div(epsf*phiHbyA)
                );
                pEqn.setReference(pRefCell_, pRefValue_);
                pEqn.solve(mesh_.solver(p.select(pimple_.finalInnerIter())));

                if (pimple_.finalNonOrthogonalIter())
                {
                    phi = phiHbyA - pEqn.flux()/epsf;
                }
            }

            U = HbyA - rAU*eps*fvc::grad(p)/rho;
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


scalar AirSolver::airMass() const
{
    return gSum(rho_.value()*voidfraction_.primitiveField()*mesh_.V().field());
}

} // namespace granair
} // namespace Foam
