// ErrorExit.cpp: see ErrorExit.hpp.
#include "core/ErrorExit.hpp"

#include <cstdlib>
#include <iostream>
#include <vector>

namespace granair {

ErrorExit::ErrorExit(MPI_Comm world) { MPI_Comm_dup(world, &comm_); }

void ErrorExit::fail(const std::string& program, const std::string& message, double wait) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm_, &rank);
    MPI_Comm_size(comm_, &size);
    MPI_Request req;
    MPI_Ibarrier(comm_, &req);
    int done = 0;
    const double start = MPI_Wtime();
    while (!done && MPI_Wtime() - start < wait) MPI_Test(&req, &done, MPI_STATUS_IGNORE);
    if (!done) {
        std::cerr << "\n" << program << ": ERROR (rank " << rank << "): " << message << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    // Every rank failed: print rank 0's message once, and any that differ.
    int len = static_cast<int>(message.size());
    MPI_Bcast(&len, 1, MPI_INT, 0, comm_);
    std::vector<char> first(message.begin(), message.end());
    first.resize(len);
    MPI_Bcast(first.data(), len, MPI_CHAR, 0, comm_);
    if (rank == 0)
        std::cerr << "\n" << program << ": ERROR: " << message << std::endl;
    else if (std::string(first.begin(), first.end()) != message)
        std::cerr << "\n" << program << ": ERROR (rank " << rank << "): " << message << std::endl;
    MPI_Barrier(comm_);
    MPI_Finalize();
    std::exit(1);
}

}  // namespace granair
