// ParticleVtkWriter on several ranks: each rank writes its own piece (empty
// ones included), rank 0 indexes every rank's piece and lists the times, the
// union of the pieces is exactly the particle set, and a bad call on one rank
// fails on every rank before anything is written.
#include <mpi.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "../../unit/output/VtkTestReader.hpp"
#include "core/Error.hpp"
#include "output/ParticleVtkWriter.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using granair::ParticleState;
using granair::ParticleVtkWriter;
using granair::Vec3;

namespace {

int rank() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int size() {
    int s = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
}

// A directory name chosen by rank 0 and shared by all ranks (not created:
// the writer must create it).
std::string sharedTempDir(const std::string& tag) {
    std::string path;
    if (rank() == 0) {
        path = (fs::temp_directory_path() / ("granair-vtk-mpi-" + tag + "-" + std::to_string(::getpid())))
                   .string();
        fs::remove_all(path);
    }
    int len = static_cast<int>(path.size());
    MPI_Bcast(&len, 1, MPI_INT, 0, MPI_COMM_WORLD);
    path.resize(len);
    MPI_Bcast(&path[0], len, MPI_CHAR, 0, MPI_COMM_WORLD);
    return path;
}

// The particle with tag id, as every rank can rebuild it.
ParticleState particle(std::int64_t id) {
    ParticleState p;
    p.id = id;
    p.x = Vec3(id / 3.0, -id * 1e-3, 1.0 / (id + 7));
    p.v = Vec3(id * 0.1, -1.0 / id, 2.5);
    p.radius = 1e-4 * id;
    return p;
}
Vec3 force(std::int64_t id) { return Vec3(-1.0 / (3 * id), id * 1e-9, 9.81 * id); }

// Particles 1..nPerRank[r] offset by rank: rank r owns tags 100 r + 1 ...
void makeLocal(int n, std::vector<ParticleState>& ps, std::vector<Vec3>& forces) {
    ps.clear();
    forces.clear();
    for (int i = 1; i <= n; ++i) {
        ps.push_back(particle(100 * rank() + i));
        forces.push_back(force(100 * rank() + i));
    }
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Rank 0: every piece of output k through the index, checked against the
// particles rebuilt from their tags; returns the number of particles per rank.
std::vector<std::uint64_t> checkOutput(const std::string& dir, int k) {
    const auto pieces = vtktest::tagsNamed(dir + "/" + ParticleVtkWriter::indexName(k), "PPolyData", "Piece");
    REQUIRE(static_cast<int>(pieces.size()) == size());
    std::vector<std::uint64_t> counts;
    for (int r = 0; r < size(); ++r) {
        CHECK(pieces[r].attributes.at("Source") == ParticleVtkWriter::pieceName(k, r));
        const vtktest::Piece p = vtktest::readPiece(dir + "/" + pieces[r].attributes.at("Source"));
        REQUIRE(p.arrays.size() == 7);
        counts.push_back(p.points);
        for (std::uint64_t i = 0; i < p.points; ++i) {
            const std::int64_t id = p.arrays.at("id").at<std::int64_t>(i);
            CHECK(id / 100 == r);  // written by its own rank
            const ParticleState e = particle(id);
            const Vec3 f = force(id);
            CHECK(sameBits(p.arrays.at("radius").at<double>(i), e.radius));
            for (int a = 0; a < 3; ++a) {
                CHECK(sameBits(p.arrays.at("Points").at<double>(3 * i + a), e.x[a]));
                CHECK(sameBits(p.arrays.at("velocity").at<double>(3 * i + a), e.v[a]));
                CHECK(sameBits(p.arrays.at("fluidForce").at<double>(3 * i + a), f[a]));
            }
        }
    }
    return counts;
}

}  // namespace

TEST_CASE("ParticleVtkWriter: one piece per rank, empty pieces valid, rank 0 indexes them",
          "[output][vtk][mpi]") {
    const std::string dir = sharedTempDir("pieces");
    {
        ParticleVtkWriter w(MPI_COMM_WORLD, dir);
        std::vector<ParticleState> ps;
        std::vector<Vec3> forces;
        // Output 0: only rank 0 has particles; output 1: only the last rank;
        // output 2: nobody (every piece empty).
        makeLocal(rank() == 0 ? 3 : 0, ps, forces);
        w.write(0.0, ps, forces);
        makeLocal(rank() == size() - 1 ? 2 : 0, ps, forces);
        w.write(0.05, ps, forces);
        makeLocal(0, ps, forces);
        w.write(0.1, ps, forces);
        CHECK(w.outputs() == 3);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank() == 0) {
        std::vector<std::uint64_t> first(size(), 0), second(size(), 0), third(size(), 0);
        first[0] = 3;
        second[size() - 1] = 2;
        CHECK(checkOutput(dir, 0) == first);
        CHECK(checkOutput(dir, 1) == second);
        CHECK(checkOutput(dir, 2) == third);
        const auto sets = vtktest::tagsNamed(dir + "/particles.pvd", "Collection", "DataSet");
        REQUIRE(sets.size() == 3);
        CHECK(sets[0].attributes.at("timestep") == "0");
        CHECK(sets[1].attributes.at("timestep") == "0.05");
        CHECK(sets[2].attributes.at("timestep") == "0.1");
        CHECK(sets[2].attributes.at("file") == "particles_2.pvtp");
        fs::remove_all(dir);
    }
    MPI_Barrier(MPI_COMM_WORLD);
}

TEST_CASE("ParticleVtkWriter: a bad call on one rank fails on every rank, nothing written",
          "[output][vtk][mpi]") {
    const std::string dir = sharedTempDir("bad");
    {
        ParticleVtkWriter w(MPI_COMM_WORLD, dir);
        std::vector<ParticleState> ps;
        std::vector<Vec3> forces;
        makeLocal(2, ps, forces);
        // The last rank passes one force too few.
        if (rank() == size() - 1) forces.pop_back();
        CHECK_THROWS_AS(w.write(0.0, ps, forces), granair::CollectiveError);
        CHECK(w.outputs() == 0);
        MPI_Barrier(MPI_COMM_WORLD);
        CHECK_FALSE(fs::exists(dir + "/particles_0"));
        CHECK_FALSE(fs::exists(dir + "/particles.pvd"));
        // The writer is still usable on every rank afterwards.
        makeLocal(2, ps, forces);
        w.write(0.0, ps, forces);
        CHECK(w.outputs() == 1);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank() == 0) {
        CHECK(checkOutput(dir, 0) == std::vector<std::uint64_t>(size(), 2));
        fs::remove_all(dir);
    }
    MPI_Barrier(MPI_COMM_WORLD);
}
