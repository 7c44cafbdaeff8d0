// Reading LIGGGHTS dumps into CG snapshots (cg/LiggghtsDump.hpp,
// cg/CgSnapshotReader.hpp), with the column layouts LIGGGHTS 3.8 writes
// (checked against a run: docs/cg-fields.md), and bad input: every message
// names the file, the time step and what was expected.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cg/CgSnapshotReader.hpp"
#include "core/Error.hpp"

using namespace granair;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("granair_cg_reader_" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return (path / name).string();
    }
};

std::string header(long step, const char* count, int n, const char* item, const std::string& cols) {
    std::string s = "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF " + count + "\n" +
                    std::to_string(n) + "\nITEM: BOX BOUNDS pp pp ff\n-0.01 0.01\n-0.01 0.01\n-0.005 0.02\n";
    return s + "ITEM: " + item + " " + cols + " \n";
}

// The dumps of the LIGGGHTS check run (two spheres on a mesh floor and one
// pair across the periodic x boundary), written as LIGGGHTS 3.8 writes them.
const char* atomCols = "id x y z vx vy vz radius mass f_force_side[1] f_force_side[2] f_force_side[3]";
std::string atoms(long step) {
    return header(step, "ATOMS", 3, "ATOMS", atomCols) +
           "4 -0.0094 0 0.005 0 0 0 0.00105 1.21226e-05 0 0 0\n"
           "1 0 0 0.00099 0.1 0 -0.2 0.001 1.0472e-05 0 0 0\n"
           "3 0.0095 0 0.005 0 0 0 0.001 1.0472e-05 -0.003663 0 0\n";
}
std::string pairCols(int n) {
    std::string s;
    for (int k = 1; k <= n; ++k) s += (k > 1 ? " " : "") + std::string("c_pc[") + std::to_string(k) + "]";
    return s;
}
std::string pairs(long step) {
    return header(step, "ENTRIES", 1, "ENTRIES", pairCols(12)) +
           "-0.0094 0 0.005 0.0095 0 0.005 4 3 1 2.4274 0 0 \n";
}
std::string walls(long step) {
    std::string cols;
    for (int k = 1; k <= 12; ++k) cols += (k > 1 ? " " : "") + std::string("c_wc[") + std::to_string(k) + "]";
    return header(step, "ENTRIES", 1, "ENTRIES", cols) + "0 0 0 0 0 0.00099 0 0 1 0 0 0.003663 \n";
}

}  // namespace

TEST_CASE("CG reader: particles, pairs across a periodic boundary, mesh and plane walls", "[cg][reader]") {
    TempDir d;
    d.file("particles_0.dump", atoms(0));
    d.file("particles_100.dump", atoms(100));
    d.file("pairs.dump", pairs(0) + pairs(100));  // one file, two frames
    d.file("walls.dump", walls(0) + walls(100));
    CgReadOptions o;
    o.particles = (d.path / "particles_*.dump").string();
    o.pairs = (d.path / "pairs.dump").string();
    o.walls = (d.path / "walls.dump").string();
    o.planeWalls = {CgPlaneWall{"side", 0, 0.002}};
    o.dt = 1e-6;
    const CgSnapshotReader r(o);
    CHECK(r.steps() == std::vector<long>{0, 100});
    const CgSnapshot s = r.read(100);
    CHECK(s.time == Approx(1e-4));
    CHECK(s.domain.periodic == std::array<bool, 3>{{true, true, false}});
    REQUIRE(s.particles.size() == 3);
    CHECK(s.particles[1].id == 1);
    CHECK(s.particles[1].v == Vec3(0.1, 0, -0.2));
    CHECK(s.particles[0].radius == 0.00105);
    REQUIRE(s.pairs.size() == 1);
    // force on particle 4 (at x = -0.0094) from 3 (at 0.0095, i.e. at -0.0105 across the boundary)
    CHECK(s.pairs[0].force == Vec3(2.4274, 0, 0));
    CHECK(s.pairs[0].xi[0] == Approx(-0.0094));
    CHECK(s.pairs[0].xj[0] == Approx(-0.0105).epsilon(1e-12));
    // the mesh-floor contact of particle 1, then particle 3's plane wall at x = 2 mm
    REQUIRE(s.walls.size() == 2);
    const auto& plane = s.walls[0];
    CHECK(plane.x == Vec3(0.0095, 0, 0.005));
    CHECK(plane.point == Vec3(0.002, 0, 0.005));
    CHECK(plane.force == Vec3(-0.003663, 0, 0));
    const auto& floor = s.walls[1];
    CHECK(floor.point == Vec3(0, 0, 0));
    CHECK(floor.x == Vec3(0, 0, 0.00099));
    CHECK(floor.force == Vec3(0, 0, 0.003663));
}

TEST_CASE("CG reader: bad dumps stop with the file, step and what was expected", "[cg][reader]") {
    TempDir d;
    auto readerFor = [&](const std::string& particles, const std::string& pairsText = "",
                         const std::string& layout = "pos id force") {
        CgReadOptions o;
        o.particles = d.file("p.dump", particles);
        if (!pairsText.empty()) o.pairs = d.file("c.dump", pairsText);
        o.pairLayout = layout;
        return CgSnapshotReader(o);
    };
    SECTION("a missing column") {
        std::string text = atoms(0);
        text.replace(text.find(" mass"), 5, " mess");
        CHECK_THROWS_WITH(readerFor(text).read(0), Catch::Contains("p.dump' (time step 0)") &&
                                                        Catch::Contains("mass missing") &&
                                                        Catch::Contains("dump ID all custom"));
    }
    SECTION("an unreadable file and a pattern matching nothing") {
        CgReadOptions o;
        o.particles = (d.path / "nothing_*.dump").string();
        CHECK_THROWS_WITH(CgSnapshotReader(o), Catch::Contains("particle dump: no file matches"));
        d.file("locked.dump", atoms(0));
        fs::permissions(d.path / "locked.dump", fs::perms::none);
        o.particles = (d.path / "locked.dump").string();
        if (!std::ifstream(o.particles))  // root reads anything
            CHECK_THROWS_WITH(CgSnapshotReader(o), Catch::Contains("cannot open file") && Catch::Contains("locked.dump"));
    }
    SECTION("a truncated frame, a bad number, not a dump") {
        std::string t = atoms(0);
        CHECK_THROWS_WITH(readerFor(t.substr(0, t.rfind("3 0.0095"))),
                          Catch::Contains("ends after 2 of 3 rows"));
        std::string bad = atoms(0);
        bad.replace(bad.find("0.00099"), 7, "0.0x099");
        CHECK_THROWS_WITH(readerFor(bad).read(0), Catch::Contains("line 11") && Catch::Contains("expected 12 numbers"));
        CHECK_THROWS_WITH(readerFor("hello\n"), Catch::Contains("expected 'ITEM: TIMESTEP'"));
        std::string nan = atoms(0);
        nan.replace(nan.find("0 0 0.00099"), 11, "0 nan 0.00099");
        CHECK_THROWS_WITH(readerFor(nan).read(0), Catch::Contains("row 2") && Catch::Contains("position"));
    }
    SECTION("pair dumps: layout, duplicates, missing step, history") {
        // a dump of fewer columns than the layout is fine if force, pos and id are there
        CHECK_NOTHROW(readerFor(atoms(0), pairs(0), "pos id force contactPoint").read(0));
        std::string wide = header(0, "ENTRIES", 1, "ENTRIES", pairCols(15)) +
                           "-0.0094 0 0.005 0.0095 0 0.005 4 3 1 2.4274 0 0 0 0 0\n";
        CHECK_THROWS_WITH(readerFor(atoms(0), wide).read(0), Catch::Contains("c_pc[13]") &&
                                                                  Catch::Contains("has 12 values") &&
                                                                  Catch::Contains("--pair-layout"));
        std::string twice = header(0, "ENTRIES", 2, "ENTRIES", pairCols(12)) +
                            "-0.0094 0 0.005 0.0095 0 0.005 4 3 1 2.4274 0 0\n"
                            "0.0095 0 0.005 -0.0094 0 0.005 3 4 1 -2.4274 0 0\n";
        CHECK_THROWS_WITH(readerFor(atoms(0), twice).read(0), Catch::Contains("listed twice"));
        CHECK_THROWS_WITH(readerFor(atoms(0), pairs(50)).read(0), Catch::Contains("no frame for time step 0"));
        CHECK_THROWS_WITH(CgLocalLayout::parse("pos id history force", "--pair-layout"),
                          Catch::Contains("history"));
        CHECK_THROWS_WITH(CgLocalLayout::parse("pos id", "--pair-layout"), Catch::Contains("no 'force'"));
        CHECK_THROWS_WITH(CgLocalLayout::parse("pos ids force", "--pair-layout"),
                          Catch::Contains("unknown compute pair/gran/local keyword 'ids'"));
        // without pos, positions come from the particle dump by id
        const auto s = readerFor(atoms(0), header(0, "ENTRIES", 1, "ENTRIES", pairCols(6)) + "4 3 1 2.4274 0 0\n",
                                 "id force")
                           .read(0);
        CHECK(s.pairs[0].xj[0] == Approx(-0.0105).epsilon(1e-12));
    }
}
