// ResourceUsage.cpp: see ResourceUsage.hpp.
#include "monitor/ResourceUsage.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <string>

namespace granair {

double ResourceUsage::peakResidentBytes() {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.compare(0, 6, "VmHWM:") == 0) return 1024.0 * std::strtod(line.c_str() + 6, nullptr);  // kB
    return 0;
}

double ResourceUsage::cpuSeconds() {
    rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}

void ResourceUsage::startLoop() {
    wallStart_ = MPI_Wtime();
    cpuStart_ = cpuSeconds();
}

void ResourceUsage::stopLoop() {
    loopSeconds_ = MPI_Wtime() - wallStart_;
    loopCpuSeconds_ = cpuSeconds() - cpuStart_;
}

void ResourceUsage::addStep(double particles, int nDemSteps) {
    particleSteps_ += particles * nDemSteps;
    peakParticles_ = std::max(peakParticles_, particles);
}

void ResourceUsage::report(MPI_Comm comm, long couplingSteps, const Buffers& b, std::ostream& os) const {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    // Maxima: loop wall, loop CPU, peak memory; sums: CPU, memory, buffers, cells.
    double local[3] = {loopSeconds_, loopCpuSeconds_, peakResidentBytes()}, maxima[3];
    double sums[7] = {loopCpuSeconds_, local[2], b.run, b.exchange, b.stepParticles, b.stepCells, b.cells};
    MPI_Allreduce(local, maxima, 3, MPI_DOUBLE, MPI_MAX, comm);
    MPI_Allreduce(MPI_IN_PLACE, sums, 7, MPI_DOUBLE, MPI_SUM, comm);
    if (rank != 0) return;
    const double loop = maxima[0], mib = 1024.0 * 1024.0;
    const double np = std::max(peakParticles_, 1.0), nc = std::max(sums[6], 1.0);
    char line[256];
    // The coupling loop alone (the stage timing table includes the set-up).
    std::snprintf(line, sizeof line,
                  "Coupling loop: %.3f s wall for %ld coupling steps, %.4g particle-steps, %.4g particle-steps/s\n",
                  loop, couplingSteps, particleSteps_, loop > 0 ? particleSteps_ / loop : 0.0);
    os << line;
    std::snprintf(line, sizeof line,
                  "Coupling loop CPU time (user + system): %.3f s on the busiest rank, %.3f s on all ranks\n",
                  maxima[1], sums[0]);
    os << line;
    std::snprintf(line, sizeof line, "Peak memory (VmHWM): %.1f MiB on the largest rank, %.1f MiB on all %d rank(s)\n",
                  maxima[2] / mib, sums[1] / mib, size);
    os << line;
    // Vector capacities = their high-water marks; OpenFOAM's extra fields
    // (voidfraction, Ksl, Us) and LIGGGHTS' fluid-force arrays not included.
    std::snprintf(line, sizeof line,
                  "Coupling buffers (all ranks): %.1f B/particle (run %.1f, exchange %.1f, coupling step %.1f) "
                  "for %.0f particles; %.1f B/cell for %.0f cells\n",
                  (sums[2] + sums[3] + sums[4]) / np, sums[2] / np, sums[3] / np, sums[4] / np, peakParticles_,
                  sums[5] / nc, sums[6]);
    os << line;
}

}  // namespace granair
