/*---------------------------------------------------------------------------*\
    granair: granairFoam

Description
    The coupled DEM-CFD executable. Every MPI rank runs one LIGGGHTS
    subdomain (opened as a library on MPI_COMM_WORLD) and one OpenFOAM
    subdomain, co-located in this process.

    Usage:  mpirun -np N granairFoam -case <dir> -parallel
            granairFoam -case <dir>                  (serial)
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "foamRuntime.H"

#include <mpi.h>
#include "library.h"

int main(int argc, char* argv[])
{
    Foam::granair::ensureFoamRuntime();
    argList::addNote("granair coupled DEM (LIGGGHTS) - CFD (OpenFOAM) solver");

    #include "setRootCase.H"

    // Serial OpenFOAM does not initialise MPI; LIGGGHTS needs it.
    int mpiInitialised = 0;
    MPI_Initialized(&mpiInitialised);
    const bool ownMpi = !mpiInitialised;
    if (ownMpi)
    {
        MPI_Init(&argc, &argv);
    }

    #include "createTime.H"
    #include "createMesh.H"

    const fileName caseDir = runTime.path();
    const fileName demDir = runTime.globalPath()/"dem";
    const fileName logDir = runTime.globalPath()/"log";
    if (Pstream::master())
    {
        mkDir(logDir);
    }
    MPI_Barrier(MPI_COMM_WORLD);

    const std::string screen = logDir/"screen.liggghts";
    const std::string log = logDir/"log.liggghts";
    const char* largv[] =
        {"liggghts", "-log", log.c_str(), "-screen", screen.c_str(), nullptr};
    void* lmp = nullptr;
    lammps_open(5, const_cast<char**>(largv), MPI_COMM_WORLD, &lmp);
    const std::string script = demDir/"in.liggghts";
    if (!isFile(script))
    {
        FatalErrorInFunction << "DEM input script " << script << " not found" << exit(FatalError);
    }
    lammps_file(lmp, const_cast<char*>(script.c_str()));

    const label nParticles = lammps_get_natoms(lmp);
    Info<< "granairFoam: CFD mesh " << returnReduce(mesh.nCells(), sumOp<label>())
        << " cells on " << Pstream::nProcs() << " rank(s); DEM "
        << nParticles << " particles" << nl;

    lammps_close(lmp);
    Info<< "End" << nl;
    if (ownMpi)
    {
        MPI_Finalize();
    }
    return 0;
}
