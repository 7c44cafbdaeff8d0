// liggghts.cpp: LIGGGHTS 3.8 stand-alone, as /usr/bin/liggghts (the same
// library, the same command line), but its errors reach stderr.
//
// Why: a stand-alone stage (a case's fill or settle run) writes LIGGGHTS'
// screen and log to files, so on an error the terminal shows only
// MPI_ABORT's banner, or nothing: Error::all prints "ERROR: ..." to the
// files on rank 0 and exits; Error::one prints to one rank's screen (NULL
// on ranks > 0 with -screen FILE) and calls MPI_Abort, which ends the
// process without flushing stdio, so even a screen on a pipe loses it.
// This front end installs granair's ERROR-echoing stream
// (ScreenErrorEcho.hpp, as granairFoam does) as every rank's screen, so the
// message appears on stderr as "LIGGGHTS error: ERROR: ... (see <file>)"
// the moment it is written, and makes stdout line buffered.
//
// It is built as build/bin/liggghts, ahead of /usr/bin/liggghts on the PATH
// that tools/foam-env.sh sets (case scripts, ./granair exec): every caller of
// `liggghts` gets it without a change. Options: those of LIGGGHTS (-in,
// -log, -screen, -var, -echo, ...), passed on unchanged.
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "ScreenErrorEcho.hpp"
#include "input.h"
#include "lammps.h"
#include "universe.h"

namespace {

// The value of option `flag` (e.g. -log) on the command line, or `fallback`.
std::string option(int argc, char** argv, const char* flag, const char* fallback) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], flag) == 0) return argv[i + 1];
    return fallback;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
    auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
    const std::string log = option(argc, argv, "-log", "log.liggghts");
    const std::string screen = option(argc, argv, "-screen", "the screen");
    // On rank 0 the stream writes through to LIGGGHTS' own screen (a file or
    // stdout); elsewhere the screen is NULL and only ERROR lines go out.
    std::FILE* echo = granair::dem::openScreenErrorEcho(lmp->screen, &lmp->logfile, log, screen);
    if (echo) {
        lmp->screen = echo;
        if (!lmp->universe->existflag) lmp->universe->uscreen = echo;
    }
    lmp->input->file();
    delete lmp;
    if (echo) std::fclose(echo);
    MPI_Finalize();
    return 0;
}
