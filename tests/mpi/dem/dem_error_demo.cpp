// dem_error_demo.cpp: runs LIGGGHTS through LiggghtsDriver on MPI_COMM_WORLD
// and is expected to be stopped by a LIGGGHTS error (see CMakeLists.txt).
//
//   dem_error_demo <logDir> file:<script> | run:<steps> ...
//
// Each action runs in order (runFile or advance). Returning normally means
// LIGGGHTS did not stop the job: exit 0, which the test treats as failure.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "LiggghtsDriver.hpp"
#include "core/Error.hpp"

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s <logDir> file:<script>|run:<steps> ...\n", argv[0]);
        MPI_Abort(MPI_COMM_WORLD, 2);
    }
    try {
        granair::dem::LiggghtsDriver dem(MPI_COMM_WORLD, argv[1]);
        for (int a = 2; a < argc; ++a) {
            const std::string action = argv[a];
            if (action.rfind("file:", 0) == 0)
                dem.runFile(action.substr(5));
            else if (action.rfind("run:", 0) == 0)
                dem.advance(std::atoi(action.c_str() + 4));
            else
                granair::fail<granair::InputError>("unknown action '", action, "'");
        }
    } catch (const granair::Error& e) {
        // Raised on all ranks together (raiseIfAny): report once, fail.
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (rank == 0) std::fprintf(stderr, "dem_error_demo: %s\n", e.what());
        MPI_Finalize();
        return 3;
    }
    std::fprintf(stderr, "dem_error_demo: the scripts ran without a LIGGGHTS error\n");
    MPI_Finalize();
    return 0;
}
