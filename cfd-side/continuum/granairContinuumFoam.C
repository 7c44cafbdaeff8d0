/*---------------------------------------------------------------------------*\
    granair: granairContinuumFoam

Description
    Continuum granular flow of a powder with air: two incompressible phases
    (powder at its bulk density, air) with one velocity and a VOF interface,
    as Remmelgas et al. (2019) did with interFoam. The powder's viscosity
    comes from a granular rheology (mu(I): coupling/rheology/MuI.hpp, or the
    kinetic latzSchmidt closure with a transported granular temperature T:
    GranularTemperature.H), the
    air's drag on the powder optionally from Darcy-Ergun percolation of the
    pore air (AirPercolation.H). docs/continuum-model.md describes the model.

        d(alpha)/dt + div(alpha U) = 0                           (MULES, AlphaAdvection.H)
        div(U) = 0
        d(rho U)/dt + div(rho U U) = -grad(p_rgh) - (g.x) grad(rho)
                                     + div(mu (grad U + grad U^T)) - grad(p_a)
        p = p_rgh + rho (g.x - g.hRef)   the mixture pressure the rheology sees

    Pressure-velocity coupling: PIMPLE, as interFoam (p_rgh, face-based
    gravity and air force). Time step from maxCo and maxAlphaCo.

Files
    constant/granularProperties (GranularMixture.H, AirPercolation.H, and
        outletPatch <name>;  the patch the discharge goes through, default outlet),
    constant/g, optional constant/hRef,
    0/U, 0/p_rgh, 0/alpha.powder, 0/p_air (darcyErgun), 0/T (latzSchmidt),
    system/fvSolution: solvers { alpha.powder p_rgh p_rghFinal U p_air T },
        PIMPLE { nOuterCorrectors nCorrectors nNonOrthogonalCorrectors momentumPredictor },
    system/controlDict: adjustTimeStep, maxCo, maxAlphaCo, maxDeltaT.
    Output: postProcessing/timeSeries.csv (PowderBalance.H), time directories.

Reference
    Remmelgas, J. et al. (2019), Eur. J. Pharm. Sci. (mu(I) rheology of MCC
    spheres, hopper discharge with interFoam); Jop, Forterre & Pouliquen
    (2006) Nature 441:727.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "pimpleControl.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "uniformDimensionedFields.H"
#include "foamRuntime.H"

#include "AirPercolation.H"
#include "AlphaAdvection.H"
#include "GranularMixture.H"
#include "PowderBalance.H"
#include "Reconstruct.H"
#include "TimeControls.H"
using Foam::granair::reconstructVector;
#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace
{

// Largest face-flux Courant number over all cells, and over cells near the
// interface (0.01 < alpha < 0.99), as interFoam's CourantNo/alphaCourantNo.
void courantNumbers
(
    const surfaceScalarField& phi,
    const volScalarField& alpha,
    scalar& co,
    scalar& alphaCo
)
{
    const fvMesh& mesh = phi.mesh();
    const scalarField sumPhi(fvc::surfaceSum(mag(phi))().primitiveField()/mesh.V().field());
    const scalarField interface(pos0(alpha.primitiveField() - 0.01)*pos0(0.99 - alpha.primitiveField()));
    const scalar dt = mesh.time().deltaTValue();
    co = 0.5*gMax(sumPhi)*dt;
    alphaCo = 0.5*gMax(interface*sumPhi)*dt;
}

// interFoam's setDeltaT: grow by at most 20 % a step, shrink at once.
void adjustDeltaT(Time& runTime, scalar co, scalar alphaCo)
{
    const dictionary& c = runTime.controlDict();
    if (!c.lookupOrDefault("adjustTimeStep", false)) return;
    const scalar maxCo = c.get<scalar>("maxCo");
    const scalar maxAlphaCo = c.lookupOrDefault<scalar>("maxAlphaCo", maxCo);
    const scalar maxDeltaT = c.lookupOrDefault<scalar>("maxDeltaT", GREAT);
    const scalar factor = min(maxCo/(co + SMALL), maxAlphaCo/(alphaCo + SMALL));
    const scalar dt = runTime.deltaTValue();
    runTime.setDeltaT(min(min(factor*dt, (1.0 + 0.2*factor)*dt), min(1.2*dt, maxDeltaT)));
}

} // namespace

int main(int argc, char* argv[])
{
    Foam::granair::ensureFoamRuntime();
    argList::addNote("continuum granular flow (mu(I) or latzSchmidt) of a powder with air: VOF mixture, optional Darcy-Ergun air drag");
    #include "setRootCase.H"
    Foam::granair::MpiSession mpi(argc, argv);
    #include "createTime.H"
    Foam::granair::checkTimeControls(runTime);
    #include "createMesh.H"

    try
    {
        const auto properties = ::granair::Dictionary::fromFile
        (
            runTime.globalPath()/"constant"/"granularProperties"
        );
        pimpleControl pimple(mesh);

        #include "readGravitationalAcceleration.H"
        #include "readhRef.H"
        #include "gh.H"

        Info<< "Reading field p_rgh\n" << endl;
        volScalarField p_rgh
        (
            IOobject("p_rgh", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
            mesh
        );
        Info<< "Reading field U\n" << endl;
        volVectorField U
        (
            IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
            mesh
        );
        #include "createPhi.H"

        Foam::granair::GranularMixture mixture(mesh, properties);
        volScalarField& alpha = mixture.alpha();
        volScalarField& rho = mixture.rho();
        const dimensionedScalar rhoPowder("rhoPowder", dimDensity, mixture.rhoPowder());
        const dimensionedScalar rhoAir("rhoAir", dimDensity, mixture.rhoAir());

        surfaceScalarField alphaPhi
        (
            IOobject("alphaPhi", runTime.timeName(), mesh),
            fvc::interpolate(alpha)*phi
        );
        surfaceScalarField rhoPhi
        (
            IOobject("rhoPhi", runTime.timeName(), mesh),
            fvc::interpolate(rho)*phi
        );

        volScalarField p
        (
            IOobject("p", runTime.timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
            p_rgh + rho*gh
        );
        label pRefCell = 0;
        scalar pRefValue = 0.0;
        setRefCell(p, p_rgh, pimple.dict(), pRefCell, pRefValue);
        if (p_rgh.needReference())
        {
            p += dimensionedScalar("p", p.dimensions(), pRefValue - getRefCellValue(p, pRefCell));
            p_rgh = p - rho*gh;
        }
        mesh.setFluxRequired(p_rgh.name());
        mesh.setFluxRequired(alpha.name());

        Foam::granair::AirPercolation air(mesh, properties, mixture);
        Foam::granair::PowderBalance balance
        (
            mesh,
            properties.getString("outletPatch", "outlet"),
            mixture.rhoPowder(),
            alpha,
            air.enabled(),
            runTime.globalPath()/"postProcessing"
        );

        Info<< "granairContinuumFoam: rheology " << mixture.rheology().name().c_str()
            << ", air model " << (air.enabled() ? "darcyErgun" : "none") << ", "
            << returnReduce(mesh.nCells(), sumOp<label>()) << " cells" << nl << endl;

        const bool transposeStress = pimple.dict().lookupOrDefault<Switch>("transposeStress", true);
        scalar cumulativeContErr = 0;
        while (runTime.run())
        {
            scalar co = 0, alphaCo = 0;
            courantNumbers(phi, alpha, co, alphaCo);
            adjustDeltaT(runTime, co, alphaCo);
            ++runTime;
            Info<< "Time = " << runTime.timeName() << "  deltaT = " << runTime.deltaTValue()
                << "  Co = " << co << "  alphaCo = " << alphaCo << endl;

            while (pimple.loop())
            {
                if (pimple.firstIter())
                {
                    Foam::granair::advectAlpha(alpha, phi, alphaPhi);
                    rhoPhi = alphaPhi*(rhoPowder - rhoAir) + phi*rhoAir;
                    mixture.correctDensity();
                }
                // The viscosity at the latest U and p in every outer corrector, so
                // nOuterCorrectors > 1 converges the rheology with the pressure
                // (with 1 corrector it lags one step, as interFoam's).
                mixture.correctViscosity(U, phi, p);
                if (pimple.firstIter())
                {
                    air.solve(mixture, alphaPhi, phi);
                }
                const surfaceScalarField airForce(air.faceForce());
                const volScalarField& mu = mixture.mu();

                // Momentum: viscous stress div(mu (grad U + grad U^T)), the grad U part
                // implicit, the transpose part explicit (as OpenFOAM's laminar
                // models; for div U = 0 it is grad(mu).grad U^T, zero where mu is
                // uniform). PIMPLE { transposeStress off; } leaves it out
                // (docs/continuum-model.md: its effect on the discharge rate). gradU is a
                // named field: T() of a temporary transposes in place (Reconstruct.H).
                fvVectorMatrix UEqn
                (
                    fvm::ddt(rho, U) + fvm::div(rhoPhi, U)
                  - fvm::laplacian(fvc::interpolate(mu), U)
                );
                if (transposeStress)
                {
                    const volTensorField gradU(fvc::grad(U));
                    const volTensorField gradUT(gradU.T());
                    UEqn -= fvc::div(mu*dev2(gradUT));
                }
                UEqn.relax();
                if (pimple.momentumPredictor())
                {
                    solve
                    (
                        UEqn
                     == reconstructVector((-ghf*fvc::snGrad(rho) - fvc::snGrad(p_rgh) + airForce)*mesh.magSf())
                    );
                }

                // Pressure correctors: interFoam's pEqn without surface tension, the
                // velocity from the face fluxes with reconstructVector (Reconstruct.H).
                while (pimple.correct())
                {
                    const volScalarField rAU(1.0/UEqn.A());
                    volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p_rgh));
                    surfaceScalarField phiHbyA
                    (
                        "phiHbyA",
                        fvc::flux(HbyA) + fvc::interpolate(rho*rAU)*fvc::ddtCorr(U, phi)
                    );
                    const surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));
                    const surfaceScalarField phig((-ghf*fvc::snGrad(rho) + airForce)*rAUf*mesh.magSf());
                    phiHbyA += phig;
                    constrainPressure(p_rgh, U, phiHbyA, rAUf);

                    while (pimple.correctNonOrthogonal())
                    {
                        fvScalarMatrix p_rghEqn(fvm::laplacian(rAUf, p_rgh) == fvc::div(phiHbyA));
                        p_rghEqn.setReference(pRefCell, getRefCellValue(p_rgh, pRefCell));
                        p_rghEqn.solve(mesh.solver(p_rgh.select(pimple.finalInnerIter())));
                        if (pimple.finalNonOrthogonalIter())
                        {
                            phi = phiHbyA - p_rghEqn.flux();
                            p_rgh.relax();
                            U = HbyA + rAU*reconstructVector((phig - p_rghEqn.flux())/rAUf);
                            U.correctBoundaryConditions();
                        }
                    }

                    const scalar contErr = runTime.deltaTValue()*mag(fvc::div(phi))().weightedAverage(mesh.V()).value();
                    cumulativeContErr += contErr;
                    Info<< "continuity error " << contErr << ", cumulative " << cumulativeContErr << endl;

                    p == p_rgh + rho*gh;
                    if (p_rgh.needReference())
                    {
                        p += dimensionedScalar("p", p.dimensions(), pRefValue - getRefCellValue(p, pRefCell));
                        p_rgh = p - rho*gh;
                    }
                }
            }

            balance.record(alpha, alphaPhi, air);
            Info<< "powder: mass flow " << balance.lastMassFlow() << " kg/s, discharged " << balance.discharged()
                << " kg, in domain " << balance.powderMass(alpha) << " kg, balance error "
                << balance.relativeBalanceError(alpha) << ", alpha in [" << gMin(alpha.primitiveField()) << ", "
                << gMax(alpha.primitiveField()) << "]" << endl;
            if (const auto* temperature = mixture.temperature())
            {
                Info<< "granular temperature T in [" << gMin(temperature->T().primitiveField()) << ", "
                    << gMax(temperature->T().primitiveField()) << "] m2/s2" << endl;
            }
            Info<< endl;

            runTime.write();
            runTime.printExecutionTime(Info);
        }

        Info<< "powder mass conservation: initial " << balance.initialMass() << " kg, in domain "
            << balance.powderMass(alpha) << " kg, discharged " << balance.discharged() << " kg, relative error "
            << balance.relativeBalanceError(alpha) << nl << "End" << nl << endl;
    }
    catch (const ::granair::Error& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    return 0;
}
