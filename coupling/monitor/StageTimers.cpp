// StageTimers.cpp: see StageTimers.hpp.
#include "monitor/StageTimers.hpp"

#include <time.h>

#include <cstdio>
#include <ostream>

namespace granair {

const char* StageTimers::name(Stage s) {
    static const char* names[] = {"DEM (LIGGGHTS)", "CFD (air solver)", "void fraction + mapping",
                                  "exchange (MPI)", "output", "other"};
    return names[s];
}

StageTimers::StageTimers() : start_(MPI_Wtime()), cpuStart_(threadCpuSeconds()) {}

double StageTimers::threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void StageTimers::report(MPI_Comm comm, std::ostream& os) const {
    std::array<double, NStages> mx{}, cpu{};
    MPI_Allreduce(seconds_.data(), mx.data(), NStages, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(cpu_.data(), cpu.data(), NStages, MPI_DOUBLE, MPI_MAX, comm);
    double wall = elapsed(), cpuTotal = threadCpuSeconds() - cpuStart_;
    MPI_Allreduce(MPI_IN_PLACE, &wall, 1, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(MPI_IN_PLACE, &cpuTotal, 1, MPI_DOUBLE, MPI_MAX, comm);
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank != 0) return;
    char line[160];
    os << "Timing breakdown (max over ranks; wall time, then CPU time):\n";
    double accounted = 0, cpuAccounted = 0;
    for (int s = 0; s < NStages; ++s) {
        if (s == Other) continue;
        accounted += mx[s];
        cpuAccounted += cpu[s];
        std::snprintf(line, sizeof line, "  %-26s %10.2f s  %6.2f %%   cpu %10.3f s  %6.2f %%\n", name(Stage(s)),
                      mx[s], wall > 0 ? 100 * mx[s] / wall : 0.0, cpu[s],
                      cpuTotal > 0 ? 100 * cpu[s] / cpuTotal : 0.0);
        os << line;
    }
    const double rest = wall - accounted > 0 ? wall - accounted : 0;
    const double cpuRest = cpuTotal - cpuAccounted > 0 ? cpuTotal - cpuAccounted : 0;
    std::snprintf(line, sizeof line, "  %-26s %10.2f s  %6.2f %%   cpu %10.3f s  %6.2f %%\n",
                  "other (setup, waits)", rest, wall > 0 ? 100 * rest / wall : 0.0, cpuRest,
                  cpuTotal > 0 ? 100 * cpuRest / cpuTotal : 0.0);
    os << line;
    std::snprintf(line, sizeof line, "  %-26s %10.2f s         cpu %10.3f s\n", "total wall time", wall, cpuTotal);
    os << line;
}

}  // namespace granair
