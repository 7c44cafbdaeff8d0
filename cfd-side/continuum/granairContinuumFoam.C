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
        [dilatancy on (Dilatancy.H): d(alpha)/dt + div(alpha U) = div(U) = S,
         S = -(alpha/phi) Dphi/Dt from phi relaxing to phi(I); the grains
         alpha phi conserved; rho = rho_p alpha phi + rho_air (1 - alpha phi)]
        d(rho U)/dt + div(rho U U) = -grad(p_rgh) - (g.x) grad(rho)
                                     + div(mu (grad U + grad U^T)) - grad(p_a)
        p = p_rgh + rho (g.x - g.hRef)   the mixture pressure the rheology sees

    Pressure-velocity coupling: PIMPLE as interFoam (p_rgh, face-based
    gravity and air force), with outer correctors under residual control
    or (the default) one per step as a semi-implicit time march
    (OuterCorrectors.H: why), an inertial projection in the pressure
    correction, the stress split so that its transpose part is stable, and
    harmonic face viscosity. Time step from maxCo and maxAlphaCo.

Files
    constant/granularProperties (GranularMixture.H, AirPercolation.H, Dilatancy.H, and
        outletPatch <name>;  the patch the discharge goes through, default outlet;
        acceleration (ax ay az);  optional uniform acceleration besides g [m/s2];
        orificeHeight h;     optional: outlet dp/dz measured on the plane z = h, PowderBalance.H),
    constant/g, optional constant/hRef,
    0/U, 0/p_rgh, 0/alpha.powder, 0/p_air (darcyErgun), 0/T (latzSchmidt),
    system/fvSolution: solvers { alpha.powder p_rgh p_rghFinal U p_air T },
        PIMPLE { nOuterCorrectors outerTolerance nCorrectors nNonOrthogonalCorrectors
                 momentumPredictor pressureCorrection transposeStress } (OuterCorrectors.H),
    0/U walls: noSlip, slip or coulombWallSlip (Coulomb wall friction,
        CoulombWallSlipFvPatchVectorField.H),
    system/controlDict: adjustTimeStep, maxCo, maxAlphaCo, maxDeltaT.
    Output: postProcessing/timeSeries.csv (PowderBalance.H), time directories.

Reference
    Remmelgas, J. et al. (2019), Eur. J. Pharm. Sci. (mu(I) rheology of MCC
    spheres, hopper discharge with interFoam); Jop, Forterre & Pouliquen
    (2006) Nature 441:727.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "adjustPhi.H"
#include "uniformDimensionedFields.H"
#include "foamRuntime.H"

#include "AirPercolation.H"
#include "AlphaAdvection.H"
#include "Dilatancy.H"
#include "GranularMixture.H"
#include "OuterCorrectors.H"
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

// p_rgh of the powder at rest: with U = 0 the face fluxes must balance the
// face-based gravity force alone, laplacian(p_rgh) = div(-ghf snGrad(rho) |Sf|)
// (unit coefficient), with the case's pressure boundary conditions.
void hydrostaticStart
(
    volScalarField& p_rgh,
    volScalarField& p,
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& gh,
    const surfaceScalarField& ghf,
    label pRefCell,
    scalar pRefValue,
    label nNonOrth
)
{
    const fvMesh& mesh = p_rgh.mesh();
    const surfaceScalarField unit
    (
        IOobject("unit", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar("unit", dimless, 1.0)
    );
    const surfaceScalarField phig(-ghf*fvc::snGrad(rho)*mesh.magSf());
    constrainPressure(p_rgh, U, phig, unit);
    for (label nonOrth = 0; nonOrth <= nNonOrth; ++nonOrth)
    {
        fvScalarMatrix p_rghEqn(fvm::laplacian(unit, p_rgh) == fvc::div(phig));
        p_rghEqn.setReference(pRefCell, getRefCellValue(p_rgh, pRefCell));
        p_rghEqn.solve(mesh.solver(p_rgh.select(true)));
    }
    p == p_rgh + rho*gh;
    if (p_rgh.needReference())
    {
        p += dimensionedScalar("p", p.dimensions(), pRefValue - getRefCellValue(p, pRefCell));
        p_rgh = p - rho*gh;
    }
    Info<< "initial pressure: hydrostatic, p in [" << gMin(p.primitiveField()) << ", " << gMax(p.primitiveField())
        << "] Pa" << nl << endl;
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
        const Foam::granair::OuterCorrectors outer(mesh);

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
        setRefCell(p, p_rgh, outer.dict(), pRefCell, pRefValue);
        if (p_rgh.needReference())
        {
            p += dimensionedScalar("p", p.dimensions(), pRefValue - getRefCellValue(p, pRefCell));
            p_rgh = p - rho*gh;
        }
        mesh.setFluxRequired(p_rgh.name());
        mesh.setFluxRequired(alpha.name());

        // The solid fraction fed back into the powder's volume (opt-in,
        // `dilatancy on;`): Dilatancy.H.
        Foam::granair::Dilatancy dilatancy(mesh, properties, mixture);
        if (dilatancy.enabled())
        {
            dilatancy.correctDensity(rho, mixture.rhoAir());
            rhoPhi = fvc::interpolate(rho)*phi;
        }
        // The volume fraction whose density the powder mass is counted with:
        // alpha at rho_b, or the grains' at rho_p.
        const volScalarField& content = dilatancy.enabled() ? dilatancy.grains() : alpha;
        const surfaceScalarField& contentFlux = dilatancy.enabled() ? dilatancy.grainFlux() : alphaPhi;

        Foam::granair::AirPercolation air(mesh, properties, mixture);
        // An optional uniform acceleration [m/s2] besides g: the along-slope
        // part of gravity on a periodic inclined plane, which cannot enter
        // through g.h (p_rgh = p - rho g.h would jump across the cyclic).
        const ::granair::Vec3 a = properties.getVec3("acceleration", ::granair::Vec3::Zero());
        const dimensionedVector acceleration("acceleration", dimAcceleration, vector(a[0], a[1], a[2]));
        Foam::granair::PowderBalance balance
        (
            mesh,
            properties.getString("outletPatch", "outlet"),
            dilatancy.enabled() ? dilatancy.rhoParticle() : mixture.rhoPowder(),
            content,
            air.enabled(),
            runTime.globalPath()/"postProcessing",
            properties.getDouble("orificeHeight", VGREAT)
        );

        Info<< "granairContinuumFoam: rheology " << mixture.rheology().name().c_str()
            << ", air model " << (air.enabled() ? "darcyErgun" : "none") << ", "
            << returnReduce(mesh.nCells(), sumOp<label>()) << " cells" << nl << endl;

        // The powder starts at rest: its pressure is the hydrostatic one, the
        // projection of gravity with U = 0 (as Basilisk's sandglass starts
        // from the lithostatic pressure), so the first viscosity sees p > 0
        // in the powder and not the p_rgh = 0 of 0/p_rgh.
        if (gMax(mag(U.primitiveField())) == 0)
        {
            hydrostaticStart(p_rgh, p, U, rho, gh, ghf, pRefCell, pRefValue, outer.nNonOrth);
        }

        scalar cumulativeContErr = 0;
        while (runTime.run())
        {
            scalar co = 0, alphaCo = 0;
            courantNumbers(phi, alpha, co, alphaCo);
            adjustDeltaT(runTime, co, alphaCo);
            ++runTime;
            Info<< "Time = " << runTime.timeName() << "  deltaT = " << runTime.deltaTValue()
                << "  Co = " << co << "  alphaCo = " << alphaCo << endl;

            // Explicit (MULES) powder transport with the fluxes of the last step.
            if (dilatancy.enabled())
            {
                Foam::granair::advectAlphaDilatant(alpha, phi, alphaPhi);
                dilatancy.transport(alpha, alphaPhi);
                rhoPhi = dilatancy.massFlux(phi, mixture.rhoAir());
                dilatancy.correctDensity(rho, mixture.rhoAir());
            }
            else
            {
                Foam::granair::advectAlpha(alpha, phi, alphaPhi);
                rhoPhi = alphaPhi*(rhoPowder - rhoAir) + phi*rhoAir;
                mixture.correctDensity();
            }

            // Outer correctors (OuterCorrectors.H): relaxed (relaxationFactors
            // U, p_rgh) until converged, then one final, unrelaxed corrector (UFinal,
            // p_rghFinal): a PISO step from the converged state, so a step that
            // stops at nOuterCorrectors is still a stable time step.
            Foam::granair::StepStatistics step{0, GREAT, GREAT, false};
            bool finalCorr = false;
            for (label corr = 1; ; ++corr)
            {
                finalCorr = finalCorr || corr >= outer.nOuter;
                if (finalCorr)
                {
                    mesh.data::add("finalIteration", true);
                }
                const volVectorField U0("U0", U);
                const volScalarField p0("p0", p);
                p_rgh.storePrevIter();

                // Viscosity at the latest U and p (a Picard iterate of the rheology).
                mixture.correctViscosity(U, phi, p, corr == 1);
                if (dilatancy.enabled())
                {
                    // div U of this corrector, from its gammaDot and phi(I).
                    dilatancy.correctSource(mixture, runTime.deltaTValue());
                }
                if (corr == 1)
                {
                    air.solve(mixture, alphaPhi, phi);
                }
                // Face forces besides gravity: the air's, and the optional uniform
                // acceleration (rho_f a.Sf/|Sf|).
                surfaceScalarField airForce(air.faceForce());
                if (mag(acceleration.value()) > 0)
                {
                    airForce += fvc::interpolate(rho)*(acceleration & mesh.Sf())/mesh.magSf();
                }
                const surfaceScalarField muf(mixture.faceViscosity());

                // Viscous stress div(mu (grad U + grad U^T)). For div U = 0 its
                // transpose part is grad(mu).(grad U)^T, which a segregated
                // solver can only treat explicitly. Explicit beside an implicit
                // div(mu grad U) it diverges once mu dt/(rho dx^2) >> 1 at a jump
                // of mu (a strain mode is amplified by -1 per corrector); so, as
                // Jasak & Weller (2000) do for the stress of solids, the
                // implicit part carries twice the viscosity and the explicit
                // part the difference:
                //     - div(2 mu grad U) + [div(mu grad U) - div(mu grad U^T)]
                // The explicit bracket is then bounded by the implicit operator
                // (0 <= N <= M in energy), the corrector iteration contracts, and
                // at convergence the two div(mu grad U) cancel: the step solves
                // the full stress. mu on faces is harmonic (GranularMixture.H).
                tmp<fvVectorMatrix> tUEqn
                (
                    fvm::ddt(rho, U) + fvm::div(rhoPhi, U)
                );
                if (outer.transposeStress)
                {
                    const volTensorField gradU(fvc::grad(U));
                    const volTensorField gradUT(gradU.T());
                    const surfaceScalarField muf2("muf2", 2*muf);
                    tUEqn.ref() +=
                        fvc::laplacian(muf, U)
                      - fvc::div(muf*(mesh.Sf() & fvc::interpolate(dev2(gradUT))))
                      - fvm::laplacian(muf2, U);
                }
                else
                {
                    tUEqn.ref() -= fvm::laplacian(muf, U);
                }
                fvVectorMatrix& UEqn = tUEqn.ref();
                UEqn.relax();
                if (outer.momentumPredictor)
                {
                    solve
                    (
                        UEqn
                     == reconstructVector((-ghf*fvc::snGrad(rho) - fvc::snGrad(p_rgh) + airForce)*mesh.magSf())
                    );
                }

                // Pressure correctors: interFoam's p_rgh equation (face-based
                // gravity and air force), with the inertial projection when asked:
                // OuterCorrectors.H. The velocity from the face fluxes with
                // reconstructVector (Reconstruct.H).
                for (label piso = 0; piso < outer.nCorr; ++piso)
                {
                    const volScalarField rAU(1.0/UEqn.A());
                    // The velocity correction of the pressure equation: 1/A (PISO), or
                    // dt/rho (the inertial projection, OuterCorrectors.H).
                    const volScalarField rAtU("rAtU", outer.inertialProjection ? volScalarField(runTime.deltaT()/rho) : rAU);
                    const surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));
                    const surfaceScalarField rAtUf("rAtUf", fvc::interpolate(rAtU));

                    volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p_rgh));
                    surfaceScalarField phiHbyA
                    (
                        "phiHbyA",
                        fvc::flux(HbyA) + fvc::interpolate(rho*rAU)*fvc::ddtCorr(U, phi)
                    );
                    const surfaceScalarField phig((-ghf*fvc::snGrad(rho) + airForce)*rAUf*mesh.magSf());
                    phiHbyA += phig;
                    if (outer.inertialProjection)
                    {
                        // U = HbyA + rAU (F - grad p*) - rAtU grad(p - p*): the
                        // old pressure's gradient with rAU, its correction with rAtU.
                        const surfaceScalarField snGradP(fvc::snGrad(p_rgh)*mesh.magSf());
                        phiHbyA += (rAtUf - rAUf)*snGradP;
                        HbyA -= (rAU - rAtU)*reconstructVector(snGradP);
                    }
                    if (p_rgh.needReference())
                    {
                        // A closed domain: the fluxes must balance before the
                        // pressure equation can (its solution is then unique up to
                        // the reference level).
                        adjustPhi(phiHbyA, U, p_rgh);
                    }
                    constrainPressure(p_rgh, U, phiHbyA, rAtUf);

                    for (label nonOrth = 0; nonOrth <= outer.nNonOrth; ++nonOrth)
                    {
                        // div(phi) = 0, or = S with dilatancy (Dilatancy.H).
                        fvScalarMatrix p_rghEqn
                        (
                            dilatancy.enabled()
                          ? fvm::laplacian(rAtUf, p_rgh) == fvc::div(phiHbyA) - dilatancy.source()
                          : fvm::laplacian(rAtUf, p_rgh) == fvc::div(phiHbyA)
                        );
                        p_rghEqn.setReference(pRefCell, getRefCellValue(p_rgh, pRefCell));
                        const bool final = piso == outer.nCorr - 1 && nonOrth == outer.nNonOrth;
                        p_rghEqn.solve(mesh.solver(p_rgh.select(final)));
                        if (nonOrth == outer.nNonOrth)
                        {
                            // The flux from the pressure equation (continuity); the
                            // velocity from the relaxed pressure (p_rgh, SIMPLE's rule).
                            phi = phiHbyA - p_rghEqn.flux();
                            p_rgh.relax();
                            U = HbyA + rAU*reconstructVector(phig/rAUf)
                              - rAtU*reconstructVector(fvc::snGrad(p_rgh)*mesh.magSf());
                            U.correctBoundaryConditions();
                        }
                    }

                    const scalar contErr = dilatancy.enabled()
                      ? runTime.deltaTValue()*mag(fvc::div(phi) - dilatancy.source())().weightedAverage(mesh.V()).value()
                      : runTime.deltaTValue()*mag(fvc::div(phi))().weightedAverage(mesh.V()).value();
                    cumulativeContErr += contErr;

                    p == p_rgh + rho*gh;
                    if (p_rgh.needReference())
                    {
                        p += dimensionedScalar("p", p.dimensions(), pRefValue - getRefCellValue(p, pRefCell));
                        p_rgh = p - rho*gh;
                    }
                }

                const auto r = Foam::granair::OuterCorrectors::residual(U, U0, p, p0, alpha);
                step = {corr, r.U, r.p, step.converged || outer.converged(corr, r)};
                Info<< "outer corrector " << corr << (finalCorr ? " (final)" : "") << ": r_U " << r.U << " (at "
                    << r.whereU << "), r_p " << r.p << " (at " << r.whereP << ")" << endl;
                if (finalCorr) break;
                finalCorr = step.converged;
            }
            mesh.data::remove("finalIteration");
            if (!step.converged && outer.nOuter > 1)
            {
                Info<< "warning: not converged within " << outer.nOuter << " outer correctors (r_U "
                    << step.residualU << ", r_p " << step.residualP << ", tolerance " << outer.tolerance << ")"
                    << endl;
            }

            balance.record(content, contentFlux, alpha, air, p, step);
            Info<< "continuity error cumulative " << cumulativeContErr << nl
                << "powder: mass flow " << balance.lastMassFlow() << " kg/s, discharged " << balance.discharged()
                << " kg, in domain " << balance.powderMass(content) << " kg, balance error "
                << balance.relativeBalanceError(content) << ", alpha in [" << gMin(alpha.primitiveField()) << ", "
                << gMax(alpha.primitiveField()) << "], packed cells with p <= 0: " << balance.lastTensionFraction()
                << endl;
            if (dilatancy.enabled())
            {
                const volScalarField& phiP = dilatancy.solidFraction();
                const scalarField packed(pos0(alpha.primitiveField() - 0.5));
                Info<< "dilatancy: powder solid fraction in [" << gMin(phiP.primitiveField() + (1 - packed))
                    << ", " << gMax(phiP.primitiveField()*packed) << "] (alpha >= 0.5), div U in ["
                    << gMin(dilatancy.source().primitiveField()) << ", " << gMax(dilatancy.source().primitiveField())
                    << "] 1/s" << endl;
            }
            if (const auto* temperature = mixture.temperature())
            {
                Info<< "granular temperature T in [" << gMin(temperature->T().primitiveField()) << ", "
                    << gMax(temperature->T().primitiveField()) << "] m2/s2" << endl;
            }
            Info<< endl;

            runTime.write();
            runTime.printExecutionTime(Info);
        }

        balance.reportIterations();
        Info<< "powder mass conservation: initial " << balance.initialMass() << " kg, in domain "
            << balance.powderMass(content) << " kg, discharged " << balance.discharged() << " kg, relative error "
            << balance.relativeBalanceError(content) << nl << "End" << nl << endl;
    }
    catch (const ::granair::Error& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    return 0;
}
