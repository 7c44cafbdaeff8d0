// Progress.hpp: the progress line of a long run, printed by rank 0 at most
// every `interval` wall seconds:
//   t = 0.2500 / 2.0000 s (12.5%) | 1234 DEM steps/s | ETA 0h02m10s | <extra>
#pragma once
#include <iosfwd>
#include <string>

namespace granair {

class Progress {
public:
    Progress(double tStart, double tEnd, double interval = 10.0);
    // Call every coupling step; prints when due (or when force is true).
    void update(double t, long demSteps, const std::string& extra, std::ostream& os, bool force = false);

private:
    double tStart_, tEnd_, interval_;
    double wallStart_, lastPrint_;
    long stepsAtStart_ = -1;
};

}  // namespace granair
