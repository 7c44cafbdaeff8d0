// StageTimers.hpp: wall time per stage of a coupled run (DEM, CFD, void
// fraction + mapping, exchange, output), for the breakdown printed at the end
// and the benchmark ratios. Times are this rank's; report() takes the max
// over ranks (the slowest rank sets the pace).
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
        Scope(StageTimers& t, Stage s) : t_(t), s_(s), start_(MPI_Wtime()) {}
        ~Scope() { t_.add(s_, MPI_Wtime() - start_); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        StageTimers& t_;
        Stage s_;
        double start_;
    };

    StageTimers();
    void add(Stage s, double seconds) { seconds_[s] += seconds; }
    double seconds(Stage s) const { return seconds_[s]; }
    double elapsed() const { return MPI_Wtime() - start_; }  // since construction

    // Collective: max over ranks of each stage; rank 0 prints a table of
    // seconds and shares of the total wall time to os.
    void report(MPI_Comm comm, std::ostream& os) const;

private:
    std::array<double, NStages> seconds_{};
    double start_;
};

}  // namespace granair
