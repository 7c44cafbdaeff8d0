// ScreenErrorEcho.cpp: see ScreenErrorEcho.hpp.
#include "ScreenErrorEcho.hpp"

#include <stdio.h>  // fopencookie (glibc)

#include <chrono>
#include <string>
#include <thread>

namespace granair::dem {

namespace {

struct EchoState {
    std::FILE* file = nullptr;  // screen file (rank 0) or nullptr
    std::FILE** log = nullptr;  // where LIGGGHTS keeps its log stream
    std::string logPath;
    std::string screenPath;
    std::string partial;  // start of a line not yet ended by '\n'
};

// LIGGGHTS' two error formats: "ERROR: msg (file:line)" from Error::all and
// friends, "ERROR on proc N: msg (file:line)" from Error::one.
bool isErrorLine(const std::string& line) { return line.rfind("ERROR", 0) == 0; }

void echo(const EchoState& s, const std::string& line) {
    // Error::one is followed by MPI_Abort: the screen and log files are
    // never flushed (they end up empty or truncated) unless we do it here.
    if (s.file) std::fflush(s.file);
    if (s.log && *s.log) std::fflush(*s.log);
    const bool one = line.rfind("ERROR on proc", 0) == 0;
    std::string where = !one ? "see " + s.logPath
                        : s.file ? "LIGGGHTS calls MPI_Abort; see " + s.screenPath
                                 : "LIGGGHTS calls MPI_Abort";
    std::fprintf(stderr, "LIGGGHTS error: %s (%s)\n", line.c_str(), where.c_str());
    std::fflush(stderr);
    // Under mpirun the line travels through a pipe to mpirun, which stops
    // forwarding output once a rank has exited with an error or aborted:
    // LIGGGHTS' next moves (MPI_Abort, or exit(1) on the other ranks once
    // this one reaches MPI_Finalize) could come first. A short pause lets it
    // through (seen lost about once in ten runs on a loaded machine).
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
}

ssize_t echoWrite(void* cookie, const char* buf, size_t size) {
    auto* s = static_cast<EchoState*>(cookie);
    if (s->file && std::fwrite(buf, 1, size, s->file) != size) return -1;
    s->partial.append(buf, size);
    std::string::size_type start = 0, end;
    while ((end = s->partial.find('\n', start)) != std::string::npos) {
        std::string line = s->partial.substr(start, end - start);
        if (isErrorLine(line)) echo(*s, line);
        start = end + 1;
    }
    s->partial.erase(0, start);
    // A line is only of interest if it starts with ERROR; never let an
    // unterminated run of output grow without bound.
    if (s->partial.size() > 4096 && !isErrorLine(s->partial)) s->partial.clear();
    return static_cast<ssize_t>(size);
}

int echoClose(void* cookie) {
    auto* s = static_cast<EchoState*>(cookie);
    s->log = nullptr;  // LIGGGHTS may be gone (driver teardown)
    if (isErrorLine(s->partial)) echo(*s, s->partial);
    int rc = s->file ? std::fclose(s->file) : 0;
    delete s;
    return rc;
}

}  // namespace

std::FILE* openScreenErrorEcho(std::FILE* file, std::FILE** log, const std::string& logPath,
                               const std::string& screenPath) {
    auto* state = new EchoState{file, log, logPath, screenPath, {}};
    cookie_io_functions_t io{};
    io.write = echoWrite;
    io.close = echoClose;
    std::FILE* stream = fopencookie(state, "w", io);
    if (!stream) {
        delete state;
        return nullptr;
    }
    // Line buffered: an ERROR line reaches echoWrite at its '\n', before
    // LIGGGHTS gets to MPI_Abort.
    std::setvbuf(stream, nullptr, _IOLBF, BUFSIZ);
    return stream;
}

}  // namespace granair::dem
