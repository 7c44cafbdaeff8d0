// ParticleExchange on one rank (MPI_COMM_SELF): every particle is owned
// locally, in dem order; backward() is the identity on the routes; bad
// particles raise InputError naming the particle id and the bad value.
// Many-rank routing is tested in tests/mpi/exchange/.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/Error.hpp"
#include "exchange/ParticleExchange.hpp"
#include "mapping/BoxMesh.hpp"

using namespace granair;
using Catch::Matchers::Contains;

namespace {

const Vec3 kLo(0, 0, 0), kHi(1, 0.5, 2);

BoxMesh wholeMesh() { return BoxMesh(kLo, kHi, {5, 4, 6}); }

// n random particles in the mesh box, ids 100, 101, ... (not their index).
std::vector<ParticleState> randomParticles(int n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ParticleState> ps(n);
    for (int i = 0; i < n; ++i) {
        ps[i].id = 100 + i;
        for (int a = 0; a < 3; ++a) {
            ps[i].x[a] = kLo[a] + u(rng) * (kHi[a] - kLo[a]);
            ps[i].v[a] = u(rng) - 0.5;
        }
        ps[i].radius = 1e-4 * (1 + u(rng));
    }
    // Boundary points: the two far corners and an internal cell face.
    ps[0].x = kLo;
    ps[1].x = kHi;
    ps[2].x = Vec3(0.4, 0.25, 1.0);
    return ps;
}

// A list that builds each particle when read, from arrays of its own (as
// LiggghtsDriver::particles() reads LIGGGHTS' arrays), counting the reads.
class ArrayList final : public ParticleList {
public:
    explicit ArrayList(const std::vector<ParticleState>& ps) {
        for (const ParticleState& p : ps) {
            id.push_back(p.id);
            for (int a = 0; a < 3; ++a) {
                x.push_back(p.x[a]);
                v.push_back(p.v[a]);
            }
            r.push_back(p.radius);
        }
    }
    std::size_t size() const override { return id.size(); }
    ParticleState operator[](std::size_t i) const override {
        ++reads;
        ParticleState p;
        p.id = id[i];
        p.x = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        p.v = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        p.radius = r[i];
        return p;
    }
    std::vector<std::int64_t> id;
    std::vector<double> x, v, r;
    mutable std::size_t reads = 0;
};

}  // namespace

// (Few test cases: every ctest test pays an MPI start-up.)
TEST_CASE("exchange on one rank owns every particle in dem order, backward round trip", "[exchange]") {
    const BoxMesh mesh = wholeMesh();
    ParticleExchange ex(MPI_COMM_SELF, mesh);
    const auto dem = randomParticles(500, 1);
    OwnedParticles owned;
    ex.forward(dem, owned);
    REQUIRE(owned.size() == dem.size());
    for (std::size_t i = 0; i < dem.size(); ++i) {
        CHECK(owned[i].state.id == dem[i].id);
        CHECK(owned[i].state.x == dem[i].x);  // copied bit for bit
        CHECK(owned[i].state.v == dem[i].v);
        CHECK(owned[i].state.radius == dem[i].radius);
        CHECK(owned[i].cell == mesh.findCell(dem[i].x));
        CHECK(owned[i].cell >= 0);
    }
    CHECK(ex.stats().particlesSent == 500);
    CHECK(ex.stats().bytesSent == 0);  // self-sends never go through MPI
    CHECK(ex.stats().partners == 0);

    // backward() returns each value to its particle.
    std::vector<double> values, out;
    // Two steps with different particle sets: buffers are reused.
    for (int n : {300, 120}) {
        const auto dem = randomParticles(n, 2 + n);
        ex.forward(dem, owned);
        const int width = 4;
        values.clear();
        for (const auto& o : owned) {
            values.push_back(static_cast<double>(o.state.id));
            for (int a = 0; a < 3; ++a) values.push_back(o.state.x[a]);
        }
        ex.backward(values, width, out);
        REQUIRE(out.size() == dem.size() * width);
        for (std::size_t i = 0; i < dem.size(); ++i) {
            CHECK(out[i * width] == static_cast<double>(dem[i].id));
            for (int a = 0; a < 3; ++a) CHECK(out[i * width + 1 + a] == dem[i].x[a]);
        }
        // The two halves, each value written in place by the fill: the same.
        std::vector<double> halves;
        std::size_t calls = 0;
        ex.backwardFill(
            width,
            [&](std::size_t k, double* dst) {
                ++calls;
                std::copy_n(values.data() + k * width, width, dst);
            },
            halves);
        ex.backwardSend();
        CHECK(calls == owned.size());
        CHECK(halves == out);
        // With a sink instead of the array: every dem particle once, the same values.
        std::vector<double> sunk(out.size(), 0.0);
        std::vector<int> sinks(dem.size(), 0);
        ex.backwardFill(
            width, [&](std::size_t k, double* dst) { std::copy_n(values.data() + k * width, width, dst); },
            [&](std::size_t i, const double* v) {
                ++sinks[i];
                std::copy_n(v, width, sunk.data() + i * width);
            });
        ex.backwardSend();
        CHECK(sunk == out);
        CHECK(std::count(sinks.begin(), sinks.end(), 1) == static_cast<long>(dem.size()));
    }
    CHECK_THROWS_WITH(ex.backwardSend(), Contains("without backwardFill"));

    // A list read when used gives the same owned particles and cells as its
    // vector, and the owned list reads this rank's particles from it (no copy).
    {
        const auto vec = randomParticles(200, 7);
        ArrayList list(vec);
        OwnedParticles fromVec, fromList;
        ex.forward(list, fromList);
        CHECK(list.reads >= vec.size());
        ParticleExchange ex2(MPI_COMM_SELF, mesh);
        ex2.forward(vec, fromVec);
        REQUIRE(fromList.size() == fromVec.size());
        for (std::size_t k = 0; k < fromVec.size(); ++k) {
            CHECK(fromList[k].state.id == fromVec[k].state.id);
            CHECK(fromList[k].state.x == fromVec[k].state.x);
            CHECK(fromList[k].state.v == fromVec[k].state.v);
            CHECK(fromList[k].state.radius == fromVec[k].state.radius);
            CHECK(fromList[k].cell == fromVec[k].cell);
        }
        list.v[0] = 42.0;  // read through: the owned list holds no copy of its own
        CHECK(fromList.state(0).v[0] == 42.0);
    }

    // No particles at all.
    owned.add(ParticleState{}, 0);  // cleared by forward()
    ex.forward({}, owned);
    CHECK(owned.empty());
    out.resize(5);
    ex.backward({}, 3, out);
    CHECK(out.empty());
}

TEST_CASE("a particle outside the mesh is an error naming its id and position, recovery", "[exchange]") {
    const BoxMesh mesh = wholeMesh();
    ParticleExchange ex(MPI_COMM_SELF, mesh);
    auto dem = randomParticles(10, 3);
    dem[6].id = 4242;
    dem[6].x = Vec3(0.5, 0.25, 2.5);  // above the top z = 2
    OwnedParticles owned;
    CHECK_THROWS_AS(ex.forward(dem, owned), InputError);
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 4242 at (0.5 0.25 2.5) is outside the CFD mesh"));
    // No routes after a failed forward(): backward() refuses...
    std::vector<double> out;
    CHECK_THROWS_WITH(ex.backward({}, 1, out), Contains("did not succeed"));
    // ...and a good forward() afterwards works as usual.
    dem[6].x = Vec3(0.5, 0.25, 1.5);
    ex.forward(dem, owned);
    CHECK(owned.size() == 10);

    // Inside the rank's box but in none of its cells: a locator with a hole
    // (no cells where x < 0.3).
    struct HoleyMesh : BoxMesh {
        using BoxMesh::BoxMesh;
        int findCell(const Vec3& x, int hint) const override {
            return x[0] < 0.3 ? -1 : BoxMesh::findCell(x, hint);
        }
    };
    const HoleyMesh holey(kLo, kHi, {5, 4, 6});
    ParticleExchange exHoley(MPI_COMM_SELF, holey);
    for (auto& p : dem) p.x[0] = 0.5;
    dem[3].id = 77;
    dem[3].x = Vec3(0.125, 0.25, 1.0);
    CHECK_THROWS_WITH(exHoley.forward(dem, owned),
                      Contains("particle 77 at (0.125 0.25 1) is outside the CFD mesh"));
}

TEST_CASE("non-finite position or velocity and bad radius name the id and the value", "[exchange]") {
    const BoxMesh mesh = wholeMesh();
    ParticleExchange ex(MPI_COMM_SELF, mesh);
    OwnedParticles owned;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    auto dem = randomParticles(8, 5);
    dem[2].id = 31;
    dem[2].x[1] = nan;
    CHECK_THROWS_AS(ex.forward(dem, owned), InputError);
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 31 has a non-finite position") && Contains("nan"));

    dem = randomParticles(8, 5);
    dem[4].id = 32;
    dem[4].v = Vec3(0.1, nan, 0.2);
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 32") && Contains("non-finite velocity (0.1 nan 0.2)"));

    dem = randomParticles(8, 5);
    dem[5].id = 33;
    dem[5].v[2] = -inf;
    CHECK_THROWS_WITH(ex.forward(dem, owned), Contains("particle 33") && Contains("-inf"));

    dem = randomParticles(8, 5);
    dem[1].id = 34;
    dem[1].radius = -0.002;
    CHECK_THROWS_WITH(ex.forward(dem, owned), Contains("particle 34") && Contains("radius -0.002"));

    dem = randomParticles(8, 5);
    dem[1].id = 35;
    dem[1].radius = 0;
    CHECK_THROWS_WITH(ex.forward(dem, owned), Contains("particle 35") && Contains("radius 0 m"));

    dem = randomParticles(8, 5);
    dem[7].id = 36;
    dem[7].radius = nan;
    CHECK_THROWS_WITH(ex.forward(dem, owned), Contains("particle 36") && Contains("radius nan"));
}

TEST_CASE("backward rejects a wrong number of values or width, constructor a bad margin", "[exchange]") {
    const BoxMesh mesh = wholeMesh();
    ParticleExchange ex(MPI_COMM_SELF, mesh);
    const auto dem = randomParticles(20, 6);
    OwnedParticles owned;
    ex.forward(dem, owned);
    std::vector<double> out;
    CHECK_THROWS_AS(ex.backward(std::vector<double>(59), 3, out), InputError);
    CHECK_THROWS_WITH(ex.backward(std::vector<double>(59), 3, out), Contains("59 values for 20 owned"));
    CHECK_THROWS_WITH(ex.backward({}, 0, out), Contains("width = 0"));
    ex.backward(std::vector<double>(60, 1.0), 3, out);  // still usable
    CHECK(out == std::vector<double>(60, 1.0));

    CHECK_THROWS_WITH(ParticleExchange(MPI_COMM_SELF, mesh, -1e-6), Contains("margin = -1e-06"));
    CHECK_THROWS_AS(ParticleExchange(MPI_COMM_SELF, mesh, std::nan("")), InputError);
}
