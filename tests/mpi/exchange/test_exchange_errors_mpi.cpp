// ParticleExchange errors across ranks: a bad particle on ONE rank makes
// EVERY rank throw the same InputError naming it (no rank hangs), whichever
// stage finds it (the DEM owner, the single candidate, or all of several
// candidates), and the exchange is usable again afterwards.
#include <catch2/catch.hpp>
#include <limits>

#include "ExchangeScenario.hpp"
#include "core/Error.hpp"
#include "exchange/ParticleExchange.hpp"

using namespace granair;
using namespace scenario;
using Catch::Matchers::Contains;

namespace {

// A CFD slab with a hole: no cells where x < 0.2 (a region an unstructured
// mesh does not cover although it lies inside the rank's bounding box).
class HoleySlab : public BoxMesh {
public:
    HoleySlab(int part, int parts) : BoxMesh(cfdSlab(part, parts)) {}
    int findCell(const Vec3& x, int hint = -1) const override {
        return x[0] < 0.2 ? -1 : BoxMesh::findCell(x, hint);
    }
};

std::vector<ParticleState> awayFromHole(std::vector<ParticleState> dem) {
    for (auto& p : dem) p.x[0] = 0.2 + 0.8 * p.x[0];
    return dem;
}

// A good step after an error: everything still arrives (no stale messages).
void checkUsable(ParticleExchange& ex, const std::vector<ParticleState>& dem) {
    OwnedParticles owned;
    ex.forward(dem, owned);
    CHECK(globalSum(static_cast<long>(owned.size())) == globalSum(static_cast<long>(dem.size())));
    std::vector<double> ids, out;
    for (const auto& o : owned) ids.push_back(static_cast<double>(o.state.id));
    ex.backward(ids, 1, out);
    int wrong = 0;
    for (std::size_t i = 0; i < dem.size(); ++i) wrong += out[i] != static_cast<double>(dem[i].id);
    CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("a particle outside the mesh on one rank: every rank throws, naming it", "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    const BoxMesh mesh = cfdSlab(rank, size);
    ParticleExchange ex(MPI_COMM_WORLD, mesh);
    OwnedParticles owned;
    const auto good = demParticles(rank, size, 0);

    // Above the top of the box, on the last rank only.
    auto dem = good;
    if (rank == size - 1) {
        ParticleState p;
        p.id = 9999999;
        p.x = Vec3(0.5, 0.4, 1.5);
        p.radius = 1e-3;
        dem.push_back(p);
    }
    CHECK_THROWS_AS(ex.forward(dem, owned), InputError);
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 9999999 at (0.5 0.4 1.5) is outside the CFD mesh"));
    std::vector<double> out;
    CHECK_THROWS_WITH(ex.backward({}, 1, out), Contains("did not succeed"));
    checkUsable(ex, good);

    // A NaN velocity on rank 0 only.
    dem = good;
    if (rank == 0) dem[5].v[1] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 5 at") && Contains("non-finite velocity") && Contains("nan"));
    checkUsable(ex, good);
}

TEST_CASE("a particle in no cell of its candidate ranks: every rank throws, naming it", "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    const HoleySlab mesh(rank, size);
    ParticleExchange ex(MPI_COMM_WORLD, mesh);
    OwnedParticles owned;
    const auto good = awayFromHole(demParticles(rank, size, 0));

    // Inside the last slab's box but in its hole, held by rank 0: found
    // missing by its only candidate (the last rank, or rank 0 itself).
    auto dem = good;
    if (rank == 0) {
        ParticleState p;
        p.id = 8888888;
        p.x = Vec3(0.1, 0.4, 1.15);
        p.radius = 1e-3;
        dem.push_back(p);
    }
    CHECK_THROWS_WITH(ex.forward(dem, owned),
                      Contains("particle 8888888 at (0.1 0.4 1.15) is outside the CFD mesh"));
    checkUsable(ex, good);

    // On the face between the first two slabs, in the hole, held by the last
    // rank: both candidates miss it, so its DEM owner reports it.
    if (size > 1) {
        dem = good;
        const double face = cfdFaces(size)[0];
        if (rank == size - 1) {
            ParticleState p;
            p.id = 7777777;
            p.x = Vec3(0.1, 0.4, face);
            p.radius = 1e-3;
            dem.push_back(p);
        }
        CHECK_THROWS_WITH(ex.forward(dem, owned),
                          Contains("particle 7777777 at (0.1 0.4 ") &&
                              Contains("is outside the CFD mesh (none of the 2 ranks"));
        checkUsable(ex, good);
    }
}

TEST_CASE("backward with a width that differs between ranks: every rank throws", "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    if (size < 2) return;  // needs two ranks to disagree
    const BoxMesh mesh = cfdSlab(rank, size);
    ParticleExchange ex(MPI_COMM_WORLD, mesh);
    OwnedParticles owned;
    const auto dem = demParticles(rank, size, 0);
    ex.forward(dem, owned);
    const int width = rank == 0 ? 3 : 2;
    std::vector<double> out;
    CHECK_THROWS_WITH(ex.backward(std::vector<double>(owned.size() * width), width, out),
                      Contains("width differs between ranks (2 to 3)"));
    ex.backward(std::vector<double>(owned.size() * 2), 2, out);  // still usable
    CHECK(out.size() == dem.size() * 2);
}
