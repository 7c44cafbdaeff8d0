// Progress.cpp: see Progress.hpp.
#include "monitor/Progress.hpp"

#include <mpi.h>

#include <cstdio>
#include <ostream>

namespace granair {

Progress::Progress(double tStart, double tEnd, double interval)
    : tStart_(tStart), tEnd_(tEnd), interval_(interval), wallStart_(MPI_Wtime()), lastPrint_(wallStart_) {}

void Progress::update(double t, long demSteps, const std::string& extra, std::ostream& os, bool force) {
    if (stepsAtStart_ < 0) stepsAtStart_ = demSteps;
    const double now = MPI_Wtime();
    if (!force && now - lastPrint_ < interval_) return;
    lastPrint_ = now;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) return;
    const double wall = now - wallStart_;
    const double frac = tEnd_ > tStart_ ? (t - tStart_) / (tEnd_ - tStart_) : 1.0;
    const double rate = wall > 0 ? (demSteps - stepsAtStart_) / wall : 0.0;
    const double eta = frac > 0 ? wall * (1 - frac) / frac : 0.0;
    const long e = static_cast<long>(eta);
    char line[256];
    std::snprintf(line, sizeof line, "t = %.4f / %.4f s (%5.1f%%) | %.0f DEM steps/s | ETA %ldh%02ldm%02lds", t,
                  tEnd_, 100 * frac, rate, e / 3600, (e / 60) % 60, e % 60);
    os << line;
    if (!extra.empty()) os << " | " << extra;
    os << std::endl;
}

}  // namespace granair
