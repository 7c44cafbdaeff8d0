// catch_mpi_main.cpp: Catch2 main for every test executable. Initialises MPI
// (tests of the coupling layer call MPI even on one rank). Every rank prints
// its own Catch2 report (so a failure on rank 1 is visible), and a failure on
// any rank fails the run on all ranks.
#define CATCH_CONFIG_RUNNER
#include <mpi.h>

#include <catch2/catch.hpp>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    Catch::Session session;
    if (int rc = session.applyCommandLine(argc, argv); rc != 0) {
        MPI_Finalize();
        return rc;
    }
    int failed = session.run();
    int anyFailed = 0;
    MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Finalize();
    return anyFailed ? 1 : 0;
}
