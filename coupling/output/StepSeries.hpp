// StepSeries.hpp: the time series of a coupled run, one row per coupling
// step, with named fields instead of columns by position.
//
// Columns (postProcessing/timeSeries.{csv,h5}, docs/case-format.md):
//   t                                      always
//   discharged_kg, mass_flow_kg_s          with a discharge counter
//   particles                              always
//   voidfraction_min, voidfraction_floor_hits   with the air on
//   <monitor columns>                      with the air on, in MonitorSet order
#pragma once
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "output/TimeSeriesWriter.hpp"

namespace granair {

// The global values of one coupling step.
struct StepRecord {
    double t = 0;                // [s]
    double dischargedKg = 0;     // cumulative, depth-scaled [kg]
    double massFlowKgS = 0;      // windowed, depth-scaled [kg/s]
    double particles = 0;        // in the DEM
    double voidFractionMin = 1;  // smallest mapped void fraction
    double floorHits = 0;        // cells at the floor this step
    std::vector<double> monitors;  // one per monitor column
};

class StepSeries {
public:
    struct Layout {
        bool discharge = false;
        bool air = false;
        std::vector<Column> monitorColumns;
    };
    static std::vector<Column> columns(const Layout& layout);

    // Writes <stem>.csv and <stem>.h5 (TimeSeriesWriter: a fresh series, or
    // with keepRows >= 0 the first keepRows rows of the existing one are kept
    // and the series continues after them). Collective.
    StepSeries(MPI_Comm comm, const std::string& stem, Layout layout, long keepRows = -1);

    // Collective in the sense of TimeSeriesWriter::append.
    void append(const StepRecord& record);
    // The last record appended (a default one before the first).
    const StepRecord& last() const { return last_; }
    long rows() const;
    void close();

private:
    Layout layout_;
    std::unique_ptr<TimeSeriesWriter> writer_;
    StepRecord last_;
    std::vector<double> row_;
};

}  // namespace granair
