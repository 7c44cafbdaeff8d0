/*---------------------------------------------------------------------------*\
    granair: granairFoam

Description
    The coupled DEM-CFD executable. Every MPI rank runs one LIGGGHTS
    subdomain (opened as a library on MPI_COMM_WORLD) and one OpenFOAM
    subdomain, co-located in this process (see CoupledRun.H).

    Usage:  mpirun -np N granairFoam -case <dir> -parallel
            granairFoam -case <dir>                  (serial)

    SIGTERM or SIGINT (Ctrl-C, or a batch system's kill) stop the run after
    the coupling step in hand: its fields are written, the time series is
    complete up to it, and the exit code is 143 (SIGTERM) or 130 (SIGINT).

    Errors: an error every rank meets (bad input every rank reads, or one
    raised collectively) is printed once and the job ends with exit code 1;
    an error on some ranks only aborts the whole job (MPI_Abort), so no rank
    is ever left waiting (coupling/core/ErrorExit.hpp). LIGGGHTS and OpenFOAM
    errors end the job themselves, with their message on stderr.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "foamRuntime.H"

#include "coupled/CoupledRun.H"
#include "core/ErrorExit.hpp"
#include "core/StopSignal.hpp"

#include <mpi.h>
#include <iostream>

int main(int argc, char* argv[])
{
    Foam::granair::ensureFoamRuntime();
    argList::addNote("granair coupled DEM (LIGGGHTS) - CFD (OpenFOAM) solver");

    #include "setRootCase.H"

    Foam::granair::MpiSession mpi(argc, argv);

    #include "createTime.H"
    #include "createMesh.H"

    // Created before anything can fail: see ErrorExit.hpp.
    ::granair::ErrorExit errorExit(MPI_COMM_WORLD);
    // SIGTERM / SIGINT: finish the coupling step, write, exit 128 + signal.
    ::granair::StopSignal stop;
    int stopSignal = 0;
    try
    {
        Foam::granair::CoupledRun run(runTime, mesh);
        run.run();
        run.finish();
        stopSignal = run.stopSignal();
    }
    catch (const std::exception& e)
    {
        errorExit.fail("granairFoam", e.what());
    }
    if (stopSignal)
    {
        // After LIGGGHTS is closed (CoupledRun's destructor, collective).
        ::granair::finaliseAndExit(MPI_COMM_WORLD, ::granair::StopSignal::exitCode(stopSignal));
    }
    Info<< "End" << nl << endl;
    return 0;
}
