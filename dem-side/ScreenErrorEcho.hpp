// ScreenErrorEcho.hpp: a stdio stream to install as LIGGGHTS' screen, which
// copies every LIGGGHTS ERROR line to stderr the moment it is written.
//
// Why: LIGGGHTS 3.8 has no exceptions. Error::all (and fix_error,
// compute_error) prints "ERROR: ..." on world rank 0 to the screen and log
// files, then calls MPI_Finalize and exit(1) on every rank; Error::one prints
// "ERROR on proc N: ..." to *that rank's* screen only (NULL on ranks > 0 when
// the screen is a file) and calls MPI_Abort, which in Open MPI 4.1 ends the
// process with _exit: no atexit handler and no stdio flush ever runs. So the
// only moment the message can be caught is when LIGGGHTS writes it. The
// stream is line buffered (each line reaches us at its '\n'); on rank 0 it
// also writes everything through to the screen file, on other ranks it drops
// everything except ERROR lines (LIGGGHTS prints nothing else there that a
// user needs).
#pragma once
#include <cstdio>
#include <string>

namespace granair::dem {

// Returns a new FILE* (glibc fopencookie) that forwards to `file` (may be
// nullptr: ERROR lines only) and echoes lines starting with "ERROR" to
// stderr as "LIGGGHTS error: <line> (see <path>)", where path is logPath for
// Error::all lines (they are in the log) and screenPath for Error::one lines
// (they are only in the screen file, and only if this rank has one).
// Before echoing, flushes `file` and *log (LIGGGHTS' log stream, read through
// the pointer because LIGGGHTS owns it; may be nullptr), so that both files
// are complete even if MPI_Abort follows. fclose() on the result also closes
// `file` (not the log). Returns nullptr (and leaves `file` alone) if the
// stream cannot be created.
std::FILE* openScreenErrorEcho(std::FILE* file, std::FILE** log, const std::string& logPath,
                               const std::string& screenPath);

}  // namespace granair::dem
