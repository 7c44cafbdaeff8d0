// ParticleVtkWriter on one rank (MPI_COMM_SELF): what is written reads back
// bit for bit through an independent reader (VtkTestReader.hpp), the index
// and the collection name the right files and times, an empty rank writes a
// valid empty piece, and bad calls fail before anything is written.
#include <mpi.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "VtkTestReader.hpp"
#include "core/Error.hpp"
#include "output/ParticleVtkWriter.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using granair::ParticleState;
using granair::ParticleVtkWriter;
using granair::Vec3;

namespace {

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& tag)
        : path(fs::temp_directory_path() / ("granair-vtk-" + tag + "-" + std::to_string(::getpid()))) {
        fs::remove_all(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

ParticleState particle(std::int64_t id, Vec3 x, Vec3 v, double r) {
    ParticleState p;
    p.id = id;
    p.x = x;
    p.v = v;
    p.radius = r;
    return p;
}

// Values a decimal format would round: thirds, pi, tiny and huge magnitudes,
// negative zero, a tag beyond 32 bits.
std::vector<ParticleState> awkwardParticles() {
    return {particle(1, Vec3(1.0 / 3.0, -2.0 / 3.0, M_PI * 1e-3), Vec3(0.1, -0.0, 1e-300), 5e-4),
            particle((std::int64_t(1) << 40) + 3, Vec3(1e-17, 12345.678901234567, -7.0), Vec3(-3e5, 2.5, 0.7),
                     1.0 / 7.0),
            particle(42, Vec3(0, 0, 0), Vec3(std::nextafter(1.0, 2.0), 0, 0), 2.2250738585072014e-308)};
}

std::vector<Vec3> awkwardForces() {
    return {Vec3(1e-12 / 3.0, -9.81 * 2.5e-6, 0.0), Vec3(-1.0 / 9.0, 6.02214076e23, -0.0),
            Vec3(M_E, -M_PI, std::sqrt(2.0))};
}

// Bit-for-bit equality of doubles (distinguishes -0.0 from 0.0).
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void checkPiece(const vtktest::Piece& piece, const std::vector<ParticleState>& ps,
                const std::vector<Vec3>& forces) {
    const std::size_t n = ps.size();
    REQUIRE(piece.points == n);
    REQUIRE(piece.verts == n);
    REQUIRE(piece.arrays.size() == 7);
    const auto& id = piece.arrays.at("id");
    const auto& radius = piece.arrays.at("radius");
    const auto& velocity = piece.arrays.at("velocity");
    const auto& force = piece.arrays.at("fluidForce");
    const auto& points = piece.arrays.at("Points");
    const auto& conn = piece.arrays.at("connectivity");
    const auto& offs = piece.arrays.at("offsets");
    CHECK(id.section == "PointData");
    CHECK(id.type == "Int64");
    CHECK(radius.type == "Float64");
    CHECK(velocity.components == 3);
    CHECK(force.components == 3);
    CHECK(points.section == "Points");
    CHECK(conn.section == "Verts");
    CHECK(offs.section == "Verts");
    REQUIRE(id.bytes.size() == 8 * n);
    REQUIRE(radius.bytes.size() == 8 * n);
    REQUIRE(velocity.bytes.size() == 24 * n);
    REQUIRE(force.bytes.size() == 24 * n);
    REQUIRE(points.bytes.size() == 24 * n);
    REQUIRE(conn.bytes.size() == 8 * n);
    REQUIRE(offs.bytes.size() == 8 * n);
    for (std::size_t i = 0; i < n; ++i) {
        CHECK(id.at<std::int64_t>(i) == ps[i].id);
        CHECK(sameBits(radius.at<double>(i), ps[i].radius));
        for (int a = 0; a < 3; ++a) {
            CHECK(sameBits(points.at<double>(3 * i + a), ps[i].x[a]));
            CHECK(sameBits(velocity.at<double>(3 * i + a), ps[i].v[a]));
            CHECK(sameBits(force.at<double>(3 * i + a), forces[i][a]));
        }
        // One vertex cell per point: cell i is point i; offsets are the cells' ends.
        CHECK(conn.at<std::int64_t>(i) == std::int64_t(i));
        CHECK(offs.at<std::int64_t>(i) == std::int64_t(i + 1));
    }
}

}  // namespace

TEST_CASE("ParticleVtkWriter: particles read back bit for bit, series listed in the pvd", "[output][vtk]") {
    TempDir tmp("values");
    const std::string dir = (tmp.path / "nested" / "particles").string();
    ParticleVtkWriter w(MPI_COMM_SELF, dir);
    REQUIRE(fs::is_directory(dir));  // created with its parents

    const std::vector<ParticleState> first = awkwardParticles();
    const std::vector<Vec3> firstForces = awkwardForces();
    // The second output: a different set (one particle left, one moved).
    std::vector<ParticleState> second = {first[2], first[0]};
    second[1].x += Vec3(1e-3, 0, -2e-3);
    const std::vector<Vec3> secondForces = {Vec3(1, 2, 3), Vec3(-4, 5.5, -6.25)};

    w.write(0.0, first, firstForces);
    w.write(0.1, second, secondForces);
    w.write(0.30000000000000004, second, secondForces);  // 0.1 + 0.2: must survive exactly
    CHECK(w.outputs() == 3);

    checkPiece(vtktest::readPiece(dir + "/particles_0/rank0.vtp"), first, firstForces);
    checkPiece(vtktest::readPiece(dir + "/particles_1/rank0.vtp"), second, secondForces);
    CHECK(w.pieceName(1, 0) == "particles_1/rank0.vtp");

    // Index: one piece (one rank), the same point-data arrays as the piece.
    const auto pieces = vtktest::tagsNamed(dir + "/particles_1.pvtp", "PPolyData", "Piece");
    REQUIRE(pieces.size() == 1);
    CHECK(pieces[0].attributes.at("Source") == "particles_1/rank0.vtp");
    const auto declared = vtktest::tagsNamed(dir + "/particles_1.pvtp", "PPolyData", "PDataArray");
    REQUIRE(declared.size() == 5);  // 4 point-data arrays + the points
    CHECK(declared[0].attributes.at("Name") == "id");
    CHECK(declared[1].attributes.at("Name") == "radius");
    CHECK(declared[2].attributes.at("Name") == "velocity");
    CHECK(declared[2].attributes.at("NumberOfComponents") == "3");
    CHECK(declared[3].attributes.at("Name") == "fluidForce");
    CHECK(declared[4].attributes.count("Name") == 0);

    // Collection: every output in order, times exact.
    const auto sets = vtktest::tagsNamed(w.collectionPath(), "Collection", "DataSet");
    REQUIRE(sets.size() == 3);
    const double times[] = {0.0, 0.1, 0.30000000000000004};
    for (int k = 0; k < 3; ++k) {
        CHECK(std::strtod(sets[k].attributes.at("timestep").c_str(), nullptr) == times[k]);
        CHECK(sets[k].attributes.at("file") == "particles_" + std::to_string(k) + ".pvtp");
        CHECK(fs::exists(fs::path(dir) / sets[k].attributes.at("file")));
    }
    CHECK(sets[1].attributes.at("timestep") == "0.1");  // shortest exact form
    CHECK_FALSE(fs::exists(w.collectionPath() + ".tmp"));
}

TEST_CASE("ParticleVtkWriter: an empty rank writes a valid empty piece", "[output][vtk]") {
    TempDir tmp("empty");
    ParticleVtkWriter w(MPI_COMM_SELF, tmp.path.string());
    w.write(1.5, {}, {});
    const vtktest::Piece piece = vtktest::readPiece((tmp.path / "particles_0" / "rank0.vtp").string());
    checkPiece(piece, {}, {});  // every array present, each with a zero byte count
    const auto sets = vtktest::tagsNamed(w.collectionPath(), "Collection", "DataSet");
    REQUIRE(sets.size() == 1);
    CHECK(sets[0].attributes.at("timestep") == "1.5");
}

TEST_CASE("ParticleVtkWriter: a large set streams in blocks and reads back", "[output][vtk]") {
    // More particles than one internal block (1024), not a multiple of it.
    TempDir tmp("large");
    ParticleVtkWriter w(MPI_COMM_SELF, tmp.path.string());
    std::vector<ParticleState> ps;
    std::vector<Vec3> forces;
    for (int i = 0; i < 2500; ++i) {
        ps.push_back(particle(1000 + i, Vec3(i * 1e-4, -i / 3.0, 1.0 / (i + 1)), Vec3(i, -i, 0.5 * i),
                              1e-4 + i * 1e-9));
        forces.push_back(Vec3(std::sin(i), std::cos(i), -i * 1e-6));
    }
    w.write(0.25, ps, forces);
    checkPiece(vtktest::readPiece((tmp.path / "particles_0" / "rank0.vtp").string()), ps, forces);
}

TEST_CASE("ParticleVtkWriter: bad calls fail clearly and write nothing", "[output][vtk]") {
    TempDir tmp("bad");
    ParticleVtkWriter w(MPI_COMM_SELF, tmp.path.string());
    const std::vector<ParticleState> ps = awkwardParticles();

    SECTION("one force per particle") {
        REQUIRE_THROWS_WITH(w.write(0.0, ps, {Vec3::Zero()}),
                            Contains("1 fluid forces for 3 particles") && Contains("one force per particle"));
        CHECK(w.outputs() == 0);
        CHECK_FALSE(fs::exists(tmp.path / "particles_0"));
        CHECK_FALSE(fs::exists(w.collectionPath()));
    }
    SECTION("times must increase and be finite") {
        w.write(0.5, ps, awkwardForces());
        REQUIRE_THROWS_WITH(w.write(0.5, ps, awkwardForces()),
                            Contains("time 0.5 s") && Contains("after the last output (0.5 s)"));
        REQUIRE_THROWS_WITH(w.write(std::nan(""), ps, awkwardForces()), Contains("expected a finite time"));
        CHECK(w.outputs() == 1);
        CHECK_FALSE(fs::exists(tmp.path / "particles_1"));
        CHECK(vtktest::tagsNamed(w.collectionPath(), "Collection", "DataSet").size() == 1);
    }
    SECTION("a directory that cannot be made is named") {
        const fs::path file = tmp.path / "plain-file";
        std::ofstream(file) << "not a directory\n";
        REQUIRE_THROWS_AS(ParticleVtkWriter(MPI_COMM_SELF, (file / "sub").string()), granair::InputError);
        REQUIRE_THROWS_WITH(
            ParticleVtkWriter(MPI_COMM_SELF, (file / "sub").string()),
            Contains("cannot create the particle output directory") && Contains((file / "sub").string()));
    }
    SECTION("a piece that cannot be written is named") {
        // The folder of output 0 exists as a plain file: the piece cannot be created.
        std::ofstream(tmp.path / "particles_0") << "in the way\n";
        REQUIRE_THROWS_WITH(w.write(0.0, ps, awkwardForces()), Contains("particles_0/rank0.vtp"));
        CHECK(w.outputs() == 0);
        CHECK_FALSE(fs::exists(w.collectionPath()));
    }
}
