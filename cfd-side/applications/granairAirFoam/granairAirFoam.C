/*---------------------------------------------------------------------------*\
    granair: granairAirFoam

Description
    The air solver alone, through a prescribed static bed: the void fraction
    comes from 0/voidfraction, the particles are fixed (Us = 0) and of one
    diameter, and the drag coefficient per cell follows the drag law named
    in constant/couplingProperties (coupling/coupler/BedDrag.hpp):

        drag    { type ErgunGidaspow; }
        bed     { diameter 225e-6; }          // particle diameter [m]
        monitors { <name> { type plane; ... } ... }   // see OutletMonitor.H

    K is recomputed every time step from the current air velocity, so a
    steady run converges to the drag law's own pressure drop. Used by the
    Ergun packed-bed validation (cases/ergun-packed-bed).

    Writes postProcessing/monitors.csv (+ .h5): t and, per monitor,
    <name>_p_Pa, <name>_dp<axis>_Pa_m, <name>_air_kg_s.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "foamRuntime.H"

#include "airSolver/AirSolver.H"
#include "monitor/MonitorSet.H"
#include "coupler/BedDrag.hpp"
#include "core/Error.hpp"

int main(int argc, char* argv[])
{
    Foam::granair::ensureFoamRuntime();
    argList::addNote("granair air solver through a prescribed static particle bed");
    #include "setRootCase.H"
    Foam::granair::MpiSession mpi(argc, argv);
    #include "createTime.H"
    #include "createMesh.H"

    try
    {
        const auto dict = ::granair::Dictionary::fromFile
        (
            runTime.globalPath()/"constant"/"couplingProperties"
        );
        auto law = ::granair::dragLaws().create(dict.subDict("drag"));
        const double d = dict.subDict("bed").getDouble("diameter", 1e-7, 1.0);

        Foam::granair::AirSolver air(mesh);
        const ::granair::FluidProperties fluid{air.rho(), air.mu()};
        Foam::granair::MonitorSet monitors(mesh, dict, runTime.globalPath()/"postProcessing");

        Info<< "granairAirFoam: drag law " << law->name().c_str() << ", d = " << d
            << " m, " << returnReduce(mesh.nCells(), sumOp<label>()) << " cells" << nl << endl;

        while (runTime.run())
        {
            ++runTime;
            // Drag coefficient from the current air velocity (particles at rest).
            const scalarField& eps = air.eps().primitiveField();
            const vectorField& U = air.U().primitiveField();
            scalarField& K = air.Ksl().primitiveFieldRef();
            forAll(K, celli)
            {
                K[celli] = ::granair::bedMomentumExchange(*law, d, eps[celli], mag(U[celli]), fluid);
            }
            air.Ksl().correctBoundaryConditions();
            air.solveStep();
            monitors.write(runTime.value(), air);
            runTime.write();
        }
        Info<< "air continuity error (cumulative) " << air.cumulativeContinuityError() << nl
            << "End" << nl << endl;
    }
    catch (const ::granair::Error& e)
    {
        FatalErrorInFunction << e.what() << exit(FatalError);
    }
    return 0;
}
