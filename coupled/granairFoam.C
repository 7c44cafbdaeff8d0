/*---------------------------------------------------------------------------*\
    granair: granairFoam

Description
    The coupled DEM-CFD executable. Every MPI rank runs one LIGGGHTS
    subdomain (opened as a library on MPI_COMM_WORLD) and one OpenFOAM
    subdomain, co-located in this process (see CoupledRun.H).

    Usage:  mpirun -np N granairFoam -case <dir> -parallel
            granairFoam -case <dir>                  (serial)

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
    try
    {
        Foam::granair::CoupledRun run(runTime, mesh);
        run.run();
        run.finish();
    }
    catch (const std::exception& e)
    {
        errorExit.fail("granairFoam", e.what());
    }
    Info<< "End" << nl << endl;
    return 0;
}
