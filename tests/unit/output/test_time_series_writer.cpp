// TimeSeriesWriter on one rank: what is written to the CSV and the HDF5 file
// reads back bit for bit, units are stored, and bad paths or rows fail clearly.
#include <catch2/catch.hpp>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "output/TimeSeriesWriter.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using granair::Column;
using granair::TimeSeriesWriter;

namespace {

// A fresh directory per test case, removed afterwards.
struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& tag)
        : path(fs::temp_directory_path() / ("granair-ts-" + tag + "-" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

const std::vector<Column> columns = {{"time_s", "s"}, {"discharged_mass_kg", "kg"}, {"mass_flow_kg_s", "kg/s"}};

// Values that a short %g would round: thirds, pi, tiny and huge magnitudes.
const std::vector<std::vector<double>> rows = {
    {0.0, 0.0, 0.0},
    {1.0 / 3.0, M_PI * 1e-7, -2.0 / 3.0},
    {1e-300, 123456789.123456789, 6.02214076e23},
};

std::vector<std::string> lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

std::vector<double> parseCsvRow(const std::string& line) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, ',');) v.push_back(std::strtod(field.c_str(), nullptr));
    return v;
}

std::string readStringAttribute(hid_t object, const char* name) {
    const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
    REQUIRE(attr >= 0);
    const hid_t type = H5Aget_type(attr);
    REQUIRE(H5Tget_class(type) == H5T_STRING);
    std::string buf(H5Tget_size(type), '\0');
    REQUIRE(H5Aread(attr, type, &buf[0]) >= 0);
    H5Tclose(type);
    H5Aclose(attr);
    return std::string(buf.c_str());  // up to the terminating null
}

}  // namespace

TEST_CASE("TimeSeriesWriter on one rank", "[output]") {
    SECTION("TimeSeriesWriter: CSV and HDF5 read back exactly, with units") {
        TempDir dir("exact");
        const std::string stem = (dir.path / "run").string();
        {
            TimeSeriesWriter w(MPI_COMM_WORLD, stem, columns);
            for (const auto& r : rows) w.append(r);
            w.close();
        }

        // CSV: header of column names, then one row per append, full precision.
        const auto csv = lines(stem + ".csv");
        REQUIRE(csv.size() == 4);
        CHECK(csv[0] == "time_s,discharged_mass_kg,mass_flow_kg_s");
        for (size_t i = 0; i < rows.size(); ++i) {
            INFO("CSV line " << i + 2 << ": " << csv[i + 1]);
            // Exact: written with the shortest of 15..17 significant digits that round-trips.
            CHECK(parseCsvRow(csv[i + 1]) == rows[i]);
        }

        // HDF5: one extendible chunked 1-D double dataset per column, unit attribute.
        const hid_t file = H5Fopen((stem + ".h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        REQUIRE(file >= 0);
        CHECK(readStringAttribute(file, "columns") == "time_s,discharged_mass_kg,mass_flow_kg_s");
        for (size_t c = 0; c < columns.size(); ++c) {
            INFO("column " << columns[c].name);
            const hid_t ds = H5Dopen2(file, columns[c].name.c_str(), H5P_DEFAULT);
            REQUIRE(ds >= 0);
            const hid_t space = H5Dget_space(ds);
            REQUIRE(H5Sget_simple_extent_ndims(space) == 1);
            hsize_t dims = 0, maxDims = 0;
            H5Sget_simple_extent_dims(space, &dims, &maxDims);
            CHECK(dims == rows.size());
            CHECK(maxDims == H5S_UNLIMITED);
            const hid_t dcpl = H5Dget_create_plist(ds);
            CHECK(H5Pget_layout(dcpl) == H5D_CHUNKED);
            std::vector<double> values(dims);
            REQUIRE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
            for (size_t r = 0; r < rows.size(); ++r) CHECK(values[r] == rows[r][c]);
            CHECK(readStringAttribute(ds, "unit") == columns[c].unit);
            H5Pclose(dcpl);
            H5Sclose(space);
            H5Dclose(ds);
        }
        H5Fclose(file);
    }

    SECTION("TimeSeriesWriter: CSV is flushed every row; close is idempotent; destructor closes") {
        TempDir dir("flush");
        const std::string stem = (dir.path / "run").string();
        {
            TimeSeriesWriter w(MPI_COMM_WORLD, stem, columns);
            w.append(rows[1]);
            // Readable while the writer is still open.
            const auto csv = lines(stem + ".csv");
            REQUIRE(csv.size() == 2);
            CHECK(parseCsvRow(csv[1]) == rows[1]);
            w.append(rows[2]);
            // No explicit close: the destructor must close both files.
        }
        const hid_t file = H5Fopen((stem + ".h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        REQUIRE(file >= 0);
        const hid_t ds = H5Dopen2(file, "mass_flow_kg_s", H5P_DEFAULT);
        const hid_t space = H5Dget_space(ds);
        CHECK(H5Sget_simple_extent_npoints(space) == 2);
        H5Sclose(space);
        H5Dclose(ds);
        H5Fclose(file);
        CHECK(lines(stem + ".csv").size() == 3);

        TimeSeriesWriter w(MPI_COMM_WORLD, stem, columns);
        w.close();
        CHECK_NOTHROW(w.close());
        CHECK_THROWS_AS(w.append(rows[0]), granair::Error);
    }

    SECTION("TimeSeriesWriter: a row of the wrong length throws") {
        TempDir dir("row");
        TimeSeriesWriter w(MPI_COMM_WORLD, (dir.path / "run").string(), columns);
        CHECK_THROWS_AS(w.append({1.0, 2.0}), granair::Error);
        CHECK_THROWS_WITH(w.append({1.0, 2.0, 3.0, 4.0}), Contains("row has 4 values, expected 3"));
        w.append(rows[1]);  // still usable, nothing partial was written
        w.close();
        CHECK(lines(dir.path / "run.csv").size() == 2);
    }

    SECTION("TimeSeriesWriter: unusable paths and columns give an InputError naming them") {
        // Directory missing.
        const std::string missing = "/nonexistent-granair-dir/sub/run";
        CHECK_THROWS_AS(TimeSeriesWriter(MPI_COMM_WORLD, missing, columns), granair::InputError);
        CHECK_THROWS_WITH(TimeSeriesWriter(MPI_COMM_WORLD, missing, columns),
                          Contains("'/nonexistent-granair-dir/sub/run.csv'") && Contains("No such file or directory"));

        // Not writable: the CSV path is a directory (works even when run as root,
        // where permission bits would not stop us).
        TempDir dir("badpath");
        fs::create_directory(dir.path / "a.csv");
        const std::string a = (dir.path / "a").string();
        CHECK_THROWS_WITH(TimeSeriesWriter(MPI_COMM_WORLD, a, columns), Contains("'" + a + ".csv'"));
        // The HDF5 path is a directory.
        fs::create_directory(dir.path / "b.h5");
        const std::string b = (dir.path / "b").string();
        CHECK_THROWS_AS(TimeSeriesWriter(MPI_COMM_WORLD, b, columns), granair::InputError);
        CHECK_THROWS_WITH(TimeSeriesWriter(MPI_COMM_WORLD, b, columns), Contains("'" + b + ".h5'"));

        // Columns that cannot be a CSV field / HDF5 dataset name.
        const std::string ok = (dir.path / "c").string();
        CHECK_THROWS_WITH(TimeSeriesWriter(MPI_COMM_WORLD, ok, {{"a", "s"}, {"a", "s"}}), Contains("'a' given twice"));
        CHECK_THROWS_AS(TimeSeriesWriter(MPI_COMM_WORLD, ok, {{"mass,kg", "kg"}}), granair::InputError);
        CHECK_THROWS_AS(TimeSeriesWriter(MPI_COMM_WORLD, ok, {}), granair::InputError);
    }
}
