// TimeSeriesWriter.cpp: see TimeSeriesWriter.hpp.
//
// Rank 0 of the communicator writes both files with the serial HDF5 API
// (default property lists; the library is the parallel build, but nothing here
// needs parallel I/O for a handful of scalars). Other ranks keep no file
// handles and only check the row length, so a wrong call fails on every rank.
#include "output/TimeSeriesWriter.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "output/FormatExact.hpp"
#include "output/Hdf5Util.hpp"

namespace granair {

namespace {

// Rows per HDF5 chunk: a long run appends many rows, one at a time.
constexpr hsize_t chunkRows = 256;

void checkColumns(const std::string& stem, const std::vector<Column>& columns) {
    if (columns.empty()) fail<InputError>("time series '", stem, "': no columns given");
    std::set<std::string> seen;
    for (const auto& c : columns) {
        // Names become CSV header fields and HDF5 dataset names.
        if (c.name.empty() || c.name.find_first_of(",/\"\n\r") != std::string::npos || c.name == ".")
            fail<InputError>("time series '", stem, "': column name '", c.name,
                             "' must be non-empty without , / \" or line breaks");
        if (!seen.insert(c.name).second)
            fail<InputError>("time series '", stem, "': column '", c.name, "' given twice");
    }
}

}  // namespace

struct TimeSeriesWriter::Impl {
    std::string stem;
    std::vector<Column> columns;
    bool writer = false;  // rank 0 of the communicator
    bool closed = false;
    std::FILE* csv = nullptr;
    hid_t file = -1;
    std::vector<hid_t> datasets;
    hsize_t rows = 0;
    long count = 0;  // rows on every rank (kept + appended)

    ~Impl() { release(); }

    std::string csvPath() const { return stem + ".csv"; }
    std::string h5Path() const { return stem + ".h5"; }

    // Open both files; returns "" or what went wrong (the caller raises it on
    // all ranks). Leaves nothing open on failure.
    std::string open() {
        csv = std::fopen(csvPath().c_str(), "w");
        if (!csv)
            return "cannot create time-series file '" + csvPath() + "': " + std::strerror(errno) +
                   " (does the directory exist and is it writable?)";
        for (size_t i = 0; i < columns.size(); ++i)
            std::fprintf(csv, "%s%s", i ? "," : "", columns[i].name.c_str());
        std::fputc('\n', csv);
        if (std::fflush(csv) != 0) {
            release();
            return "cannot write time-series file '" + csvPath() + "'";
        }

        QuietHdf5 quiet;
        file = H5Fcreate(h5Path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        if (file < 0) {
            release();
            return "cannot create time-series file '" + h5Path() + "' (does the directory exist and is it writable?)";
        }
        std::string order;
        for (const auto& c : columns) order += (order.empty() ? "" : ",") + c.name;
        bool ok = writeStringAttribute(file, "columns", order);
        const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = chunkRows;
        const hid_t space = H5Screate_simple(1, &zero, &unlimited);
        const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
        ok = ok && space >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, 1, &chunk) >= 0;
        for (size_t i = 0; ok && i < columns.size(); ++i) {
            const hid_t ds = H5Dcreate2(file, columns[i].name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl,
                                        H5P_DEFAULT);
            if (ds >= 0) datasets.push_back(ds);
            ok = ds >= 0 && writeStringAttribute(ds, "unit", columns[i].unit);
        }
        if (dcpl >= 0) H5Pclose(dcpl);
        if (space >= 0) H5Sclose(space);
        if (ok) ok = H5Fflush(file, H5F_SCOPE_LOCAL) >= 0;
        if (!ok) {
            release();
            return "cannot set up the datasets in time-series file '" + h5Path() + "'";
        }
        return "";
    }

    std::string header() const {
        std::string h;
        for (size_t i = 0; i < columns.size(); ++i) h += (i ? "," : "") + columns[i].name;
        return h;
    }

    // Continue an existing series after its first keepRows rows; returns ""
    // or what is wrong with the files (nothing is left open then).
    std::string resume(long keepRows) {
        std::ifstream in(csvPath());
        if (!in) return "cannot continue time series '" + csvPath() + "': the file does not exist (a restart " +
                        "continues the series of the run it restarts from)";
        std::string line, kept;
        std::getline(in, line);
        if (line != header())
            return "cannot continue time series '" + csvPath() + "': its columns '" + line +
                   "' differ from this run's '" + header() + "' (were the air, discharge or monitors changed?)";
        kept = line + "\n";
        long n = 0;
        while (n < keepRows && std::getline(in, line) && !line.empty()) {
            kept += line + "\n";
            ++n;
        }
        in.close();
        if (n < keepRows)
            return "cannot continue time series '" + csvPath() + "': it has " + std::to_string(n) +
                   " rows, the restart point needs the first " + std::to_string(keepRows);
        // Rewrite it with the kept rows (a run that went on past the restart
        // point left rows that are about to be computed again).
        const std::string tmp = csvPath() + ".restart";
        {
            std::ofstream out(tmp, std::ios::trunc);
            out << kept;
            if (!out.flush()) return "cannot write '" + tmp + "'";
        }
        if (std::rename(tmp.c_str(), csvPath().c_str()) != 0)
            return "cannot replace '" + csvPath() + "': " + std::strerror(errno);
        csv = std::fopen(csvPath().c_str(), "a");
        if (!csv) return "cannot append to time-series file '" + csvPath() + "': " + std::strerror(errno);

        QuietHdf5 quiet;
        file = H5Fopen(h5Path().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        if (file < 0) {
            release();
            return "cannot continue time series '" + h5Path() + "': it cannot be opened (missing?)";
        }
        const hsize_t keep = static_cast<hsize_t>(keepRows);
        for (const Column& c : columns) {
            const hid_t ds = H5Dopen2(file, c.name.c_str(), H5P_DEFAULT);
            hsize_t size = 0;
            const hid_t space = ds >= 0 ? H5Dget_space(ds) : -1;
            const bool ok = space >= 0 && H5Sget_simple_extent_ndims(space) == 1 &&
                            H5Sget_simple_extent_dims(space, &size, nullptr) == 1;
            if (space >= 0) H5Sclose(space);
            if (ds >= 0) datasets.push_back(ds);
            if (!ok || size < keep || H5Dset_extent(ds, &keep) < 0) {
                release();
                return "cannot continue time series '" + h5Path() + "': column '" + c.name +
                       (ok ? "' has " + std::to_string(size) + " rows, the restart point needs " +
                                 std::to_string(keepRows)
                           : "' is missing");
            }
        }
        rows = keep;
        return "";
    }

    void appendCsv(const std::vector<double>& row) {
        for (size_t i = 0; i < row.size(); ++i) std::fprintf(csv, "%s%s", i ? "," : "", formatExact(row[i]).c_str());
        std::fputc('\n', csv);
        // Flushed every row so a running job can be plotted.
        if (std::fflush(csv) != 0 || std::ferror(csv))
            fail<Error>("time series: writing '", csvPath(), "' failed: ", std::strerror(errno));
    }

    void appendHdf5(const std::vector<double>& row) {
        QuietHdf5 quiet;
        const hsize_t newSize = rows + 1, one = 1;
        for (size_t i = 0; i < row.size(); ++i) {
            const hid_t ds = datasets[i];
            bool ok = H5Dset_extent(ds, &newSize) >= 0;
            const hid_t fileSpace = ok ? H5Dget_space(ds) : -1;
            const hid_t memSpace = H5Screate_simple(1, &one, nullptr);
            ok = ok && fileSpace >= 0 && memSpace >= 0 &&
                 H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, &rows, nullptr, &one, nullptr) >= 0 &&
                 H5Dwrite(ds, H5T_NATIVE_DOUBLE, memSpace, fileSpace, H5P_DEFAULT, &row[i]) >= 0;
            if (memSpace >= 0) H5Sclose(memSpace);
            if (fileSpace >= 0) H5Sclose(fileSpace);
            if (!ok) fail<Error>("time series: writing column '", columns[i].name, "' of '", h5Path(), "' failed");
        }
        if (H5Fflush(file, H5F_SCOPE_LOCAL) < 0) fail<Error>("time series: flushing '", h5Path(), "' failed");
        ++rows;
    }

    // Close whatever is open; returns false if a close failed.
    bool release() {
        bool ok = true;
        for (hid_t ds : datasets) ok = H5Dclose(ds) >= 0 && ok;
        datasets.clear();
        if (file >= 0) ok = H5Fclose(file) >= 0 && ok;
        file = -1;
        if (csv) ok = std::fclose(csv) == 0 && ok;
        csv = nullptr;
        return ok;
    }
};

TimeSeriesWriter::TimeSeriesWriter(MPI_Comm comm, const std::string& stem, std::vector<Column> columns,
                                   long keepRows)
    : impl_(std::make_unique<Impl>()) {
    checkColumns(stem, columns);
    impl_->stem = stem;
    impl_->columns = std::move(columns);
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    impl_->writer = rank == 0;
    std::string problem;
    if (impl_->writer) problem = keepRows >= 0 ? impl_->resume(keepRows) : impl_->open();
    raiseIfAny(comm, problem);
    impl_->count = keepRows >= 0 ? keepRows : 0;
}

long TimeSeriesWriter::rows() const { return impl_->count; }

TimeSeriesWriter::~TimeSeriesWriter() {
    try {
        close();
    } catch (...) {
        // A destructor must not throw; close() explicitly to see the error.
    }
}

void TimeSeriesWriter::append(const std::vector<double>& row) {
    Impl& m = *impl_;
    if (m.closed) fail<Error>("time series '", m.stem, "': append() after close()");
    if (row.size() != m.columns.size())
        fail<Error>("time series '", m.stem, "': row has ", row.size(), " values, expected ", m.columns.size(),
                    " (one per column)");
    ++m.count;
    if (!m.writer) return;
    m.appendCsv(row);
    m.appendHdf5(row);
}

void TimeSeriesWriter::close() {
    Impl& m = *impl_;
    if (m.closed) return;
    m.closed = true;
    if (!m.release()) fail<Error>("time series '", m.stem, "': closing the files failed");
}

}  // namespace granair
