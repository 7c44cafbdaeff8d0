// TimeSeriesWriter on several ranks: only rank 0 writes (other ranks' values
// are ignored), and a path rank 0 cannot open fails on every rank together.
#include <catch2/catch.hpp>
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "output/TimeSeriesWriter.hpp"

namespace fs = std::filesystem;
using granair::TimeSeriesWriter;

namespace {
int rank() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

// A directory chosen by rank 0 and shared by all ranks.
std::string sharedTempDir() {
    std::string path;
    if (rank() == 0) {
        path = (fs::temp_directory_path() / ("granair-ts-mpi-" + std::to_string(::getpid()))).string();
        fs::remove_all(path);
        fs::create_directories(path);
    }
    int len = static_cast<int>(path.size());
    MPI_Bcast(&len, 1, MPI_INT, 0, MPI_COMM_WORLD);
    path.resize(len);
    MPI_Bcast(&path[0], len, MPI_CHAR, 0, MPI_COMM_WORLD);
    return path;
}
}  // namespace

TEST_CASE("TimeSeriesWriter: only rank 0 writes", "[output][mpi]") {
    const std::string dir = sharedTempDir();
    const std::string stem = dir + "/run";
    {
        TimeSeriesWriter w(MPI_COMM_WORLD, stem, {{"time_s", "s"}, {"mass_kg", "kg"}});
        // Each rank passes its own values; only rank 0's reach the file.
        w.append({0.5, 10.0 + rank()});
        w.append({1.0, 20.0 + rank()});
    }
    MPI_Barrier(MPI_COMM_WORLD);
    std::ifstream in(stem + ".csv");
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    CHECK(lines == std::vector<std::string>{"time_s,mass_kg", "0.5,10", "1,20"});
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank() == 0) fs::remove_all(dir);
}

TEST_CASE("TimeSeriesWriter: an unusable path throws on every rank", "[output][mpi]") {
    // Only rank 0 touches the file, but every rank must throw (no rank left
    // waiting in the next collective call).
    const std::string bad = "/nonexistent-granair-dir/run";
    CHECK_THROWS_AS(TimeSeriesWriter(MPI_COMM_WORLD, bad, {{"time_s", "s"}}), granair::InputError);
    CHECK_THROWS_WITH(TimeSeriesWriter(MPI_COMM_WORLD, bad, {{"time_s", "s"}}),
                      Catch::Matchers::Contains("'/nonexistent-granair-dir/run.csv'"));
}
