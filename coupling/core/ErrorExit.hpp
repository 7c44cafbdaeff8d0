// ErrorExit.hpp: end an MPI job on an error without ever leaving a rank
// waiting, and without the noise of an abort when it is not needed.
//
// Every executable creates an ErrorExit right after MPI is initialised (a
// collective MPI_Comm_dup). A rank that catches an error calls fail(): it
// joins a non-blocking barrier on that private communicator and waits up to
// `wait` seconds.
//  - If every rank failed (bad input that every rank reads the same way, or a
//    CollectiveError), the barrier completes: rank 0 prints its message, any
//    rank whose message differs prints its own, MPI is finalised and the
//    process exits with code 1.
//  - If some rank is still working (or blocked waiting for the failed one),
//    the barrier cannot complete: the failed rank prints its message and
//    calls MPI_Abort, which ends every rank.
#pragma once
#include <mpi.h>

#include <string>

namespace granair {

class ErrorExit {
public:
    explicit ErrorExit(MPI_Comm world = MPI_COMM_WORLD);
    [[noreturn]] void fail(const std::string& program, const std::string& message, double wait = 5.0);

private:
    MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace granair
