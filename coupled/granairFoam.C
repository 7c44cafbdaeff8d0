/*---------------------------------------------------------------------------*\
    granair: granairFoam

Description
    The coupled DEM-CFD executable. Every MPI rank runs one LIGGGHTS
    subdomain (opened as a library on MPI_COMM_WORLD) and one OpenFOAM
    subdomain, co-located in this process (see CoupledRun.H).

    Usage:  mpirun -np N granairFoam -case <dir> -parallel
            granairFoam -case <dir>                  (serial)

    Errors: an error raised on all ranks together (bad input found by every
    rank, or raised collectively) is printed once and the job ends with exit
    code 1; an error on one rank only aborts the whole job (MPI_Abort), so no
    rank is ever left waiting. LIGGGHTS and OpenFOAM errors end the job
    themselves, with their message on stderr.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "foamRuntime.H"

#include "coupled/CoupledRun.H"
#include "core/Error.hpp"

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

    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int rc = 0;
    try
    {
        Foam::granair::CoupledRun run(runTime, mesh);
        run.run();
        run.finish();
    }
    catch (const ::granair::CollectiveError& e)
    {
        if (rank == 0)
        {
            std::cerr << "\ngranairFoam: ERROR: " << e.what() << std::endl;
        }
        rc = 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "\ngranairFoam: ERROR (rank " << rank << "): " << e.what() << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
    }

    Info<< (rc ? "Stopped on error" : "End") << nl << endl;
    if (rc != 0)
    {
        // Not through OpenFOAM's exit: its parallel shutdown exits with 0.
        MPI_Finalize();
        std::exit(rc);
    }
    return 0;
}
