// StageTimers.hpp: wall time and CPU time per stage of a coupled run (DEM,
// CFD, void fraction + mapping, exchange, output), for the breakdown printed
// at the end and the benchmark ratios. Times are this rank's; report() takes
// the max over ranks (the slowest rank sets the pace). The CPU time (this
// thread's, user + system) is what the stage cost even when other processes
// share the cores: on a loaded machine the wall-time shares mix the stage's
// cost with how often the rank was descheduled during it; the CPU shares do
// not (a rank's busy wait inside MPI still counts).
#pragma once
#include <mpi.h>

#include <array>
#include <iosfwd>
#include <string>

namespace granair {

class StageTimers {
public:
    enum Stage { DEM, CFD, Mapping, Exchange, Output, Other, NStages };
    static const char* name(Stage s);

    // RAII: times one stretch of a stage.
    class Scope {
    public:
        Scope(StageTimers& t, Stage s) : t_(t), s_(s), start_(MPI_Wtime()), cpu_(threadCpuSeconds()) {}
        ~Scope() { t_.add(s_, MPI_Wtime() - start_, threadCpuSeconds() - cpu_); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        StageTimers& t_;
        Stage s_;
        double start_, cpu_;
    };

    StageTimers();
    void add(Stage s, double seconds, double cpuSeconds = 0) {
        seconds_[s] += seconds;
        cpu_[s] += cpuSeconds;
    }
    double seconds(Stage s) const { return seconds_[s]; }
    double cpuSeconds(Stage s) const { return cpu_[s]; }
    // CPU time of the calling thread [s] (CLOCK_THREAD_CPUTIME_ID; ~1 us a call).
    static double threadCpuSeconds();
    double elapsed() const { return MPI_Wtime() - start_; }  // since construction

    // Collective: max over ranks of each stage; rank 0 prints a table of
    // seconds and shares of the total wall time to os.
    void report(MPI_Comm comm, std::ostream& os) const;

private:
    std::array<double, NStages> seconds_{}, cpu_{};
    double start_, cpuStart_;
};

}  // namespace granair
