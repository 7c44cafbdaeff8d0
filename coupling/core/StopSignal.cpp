// StopSignal.cpp: see StopSignal.hpp.
#include "core/StopSignal.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace granair {

namespace {

volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_oldTerm, g_oldInt;

extern "C" void onStopSignal(int sig) {
    if (g_signal != 0) {
        // Second signal: the default action, now.
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    g_signal = sig;
}

}  // namespace

StopSignal::StopSignal() {
    g_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = onStopSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;  // MPI and file I/O carry on through the handler
    sigaction(SIGTERM, &sa, &g_oldTerm);
    sigaction(SIGINT, &sa, &g_oldInt);
}

StopSignal::~StopSignal() {
    sigaction(SIGTERM, &g_oldTerm, nullptr);
    sigaction(SIGINT, &g_oldInt, nullptr);
}

int StopSignal::local() { return g_signal; }

int StopSignal::received(MPI_Comm comm) {
    int mine = g_signal, any = 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm);
    return any;
}

const char* StopSignal::name(int signal) {
    if (signal == SIGTERM) return "SIGTERM";
    if (signal == SIGINT) return "SIGINT";
    static char buf[32];
    std::snprintf(buf, sizeof buf, "signal %d", signal);
    return buf;
}

void finaliseAndExit(MPI_Comm comm, int code) {
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Barrier(comm);
    MPI_Finalize();
    std::exit(code);
}

}  // namespace granair
