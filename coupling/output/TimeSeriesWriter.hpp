// TimeSeriesWriter.hpp: scalar time series of a run (discharged mass, mass
// flow rate, outlet pressure gradient, ...), written as HDF5 and CSV.
//
// Values are global scalars that the caller has already reduced; only the
// writing rank (rank 0 of the communicator) touches the files. The CSV is
// flushed every row so a long run can be plotted while it goes; the HDF5 file
// holds one extendible 1-D dataset per column plus the column units as
// attributes.
#pragma once
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace granair {

struct Column {
    std::string name;  // e.g. "mass_flow_kg_s"
    std::string unit;  // e.g. "kg/s"
};

class TimeSeriesWriter {
public:
    // stem: path without extension; writes stem.csv and stem.h5 (replacing
    // them). Collective over comm: if rank 0 cannot create the files, every
    // rank throws InputError naming the path.
    // keepRows >= 0 continues an existing series instead (a restart): both
    // files must exist with these columns and at least keepRows rows; the
    // rows after the first keepRows are dropped (a run that went on past the
    // restart point) and new rows follow, so no row is lost or repeated.
    // InputError on every rank, naming the file, if that is not so.
    TimeSeriesWriter(MPI_Comm comm, const std::string& stem, std::vector<Column> columns, long keepRows = -1);
    ~TimeSeriesWriter();
    TimeSeriesWriter(const TimeSeriesWriter&) = delete;
    TimeSeriesWriter& operator=(const TimeSeriesWriter&) = delete;

    // One value per column, in column order. Collective only in the sense that
    // every rank may call it; non-writing ranks ignore the values.
    void append(const std::vector<double>& row);
    void close();
    // Rows in the series so far (kept + appended), on every rank.
    long rows() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace granair
