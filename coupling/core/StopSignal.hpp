// StopSignal.hpp: SIGTERM and SIGINT end a long run cleanly.
//
// A batch system (or mpirun, forwarding a kill) sends SIGTERM; a user at the
// terminal presses Ctrl-C (SIGINT). Killing the process there and then would
// leave the outputs cut at an arbitrary point. Instead the handler only notes
// the signal; the run loop asks, once per coupling step and on all ranks
// together (one small allreduce, so every rank stops after the same step and
// none is left waiting), whether any rank got one, finishes that step, writes
// what it has and ends with exit code 128 + signal (143 for SIGTERM, 130 for
// SIGINT, the shell convention). A second signal ends the process at once
// (the default action).
#pragma once
#include <mpi.h>

namespace granair {

class StopSignal {
public:
    // Installs the handlers (restored by the destructor). One at a time.
    StopSignal();
    ~StopSignal();
    StopSignal(const StopSignal&) = delete;
    StopSignal& operator=(const StopSignal&) = delete;

    // The signal this rank received (0: none), without communication.
    static int local();
    // Collective over comm: the signal any rank received (the largest
    // number if they differ), 0 if none.
    static int received(MPI_Comm comm);
    // "SIGTERM", "SIGINT", or "signal <n>".
    static const char* name(int signal);
    // Exit code for a run stopped by `signal`: 128 + signal.
    static int exitCode(int signal) { return 128 + signal; }
};

// End an MPI program after a clean stop: every rank calls it (collective),
// MPI is finalised, the process exits with `code` (OpenFOAM's own exit at the
// end of main would always exit 0).
[[noreturn]] void finaliseAndExit(MPI_Comm comm, int code);

}  // namespace granair
