// ResourceUsage.hpp: what a coupled run cost, for the report at its end:
// wall and CPU time of the coupling loop, particle-steps per second, peak
// resident memory (VmHWM of /proc/self/status, Linux) and the bytes held by
// the coupling layer's own buffers per particle and per cell.
//
// CPU time (getrusage: user + system of this process) is less disturbed than
// wall time by other load on the machine; the benchmarks compare it.
#pragma once
#include <mpi.h>

#include <iosfwd>

namespace granair {

class ResourceUsage {
public:
    // Peak resident memory of this process [bytes]; 0 where /proc/self/status
    // does not exist.
    static double peakResidentBytes();
    // CPU time (user + system) of this process so far [s].
    static double cpuSeconds();

    void startLoop();
    void stopLoop();
    // One coupling step of nDemSteps DEM steps with `particles` particles
    // (global count).
    void addStep(double particles, int nDemSteps);
    double peakParticles() const { return peakParticles_; }

    // Bytes held by this rank's coupling buffers (vector capacities).
    struct Buffers {
        double run = 0;            // the run's own per-particle buffers
        double exchange = 0;       // ParticleExchange
        double stepParticles = 0;  // CouplingStep, per particle
        double stepCells = 0;      // CouplingStep, per cell
        double cells = 0;          // this rank's cell count
    };
    // Collective: rank 0 prints the loop time, CPU time, peak memory and
    // buffer bytes per particle / per cell (sums and maxima over ranks).
    void report(MPI_Comm comm, long couplingSteps, const Buffers& buffers, std::ostream& os) const;

private:
    double wallStart_ = 0, cpuStart_ = 0;
    double loopSeconds_ = 0, loopCpuSeconds_ = 0;
    double particleSteps_ = 0, peakParticles_ = 0;
};

}  // namespace granair
