// ParticleExchange across ranks: DEM slabs along x, CFD slabs along z (see
// ExchangeScenario.hpp). Checked against a direct computation on every rank:
// each particle reaches exactly the rank whose cells contain it, in the
// documented order, and backward() brings every value home exactly once.
// Written for any rank count (ctest runs 1, 2, 3 and 4).
#include <catch2/catch.hpp>
#include <cmath>

#include "ExchangeScenario.hpp"
#include "exchange/ParticleExchange.hpp"

using namespace granair;
using namespace scenario;

namespace {

// Stokes drag on the CFD rank, F = 3 pi mu d (U - v) = 6 pi mu r (U - v)
// (any smooth function of the particle would do; this one is physical), with
// an air velocity that varies with the cell centre.
Vec3 airVelocity(const Vec3& c) { return Vec3(1.0 + c[2], 0.5 * std::sin(3 * c[0]), c[1] - 0.3); }
Vec3 dragForce(const ParticleState& p, const Vec3& cellCentre) {
    const double mu = 1.8e-5;  // [Pa s] air
    const double beta = 6 * M_PI * mu * p.radius;
    return beta * (airVelocity(cellCentre) - p.v);
}

}  // namespace

TEST_CASE("every particle reaches exactly the rank whose cells contain it, and comes back",
          "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    std::vector<BoxMesh> slabs;
    for (int p = 0; p < size; ++p) slabs.push_back(cfdSlab(p, size));
    std::vector<const CellLocator*> meshes;
    for (const auto& s : slabs) meshes.push_back(&s);
    const BoxMesh& mesh = slabs[rank];

    ParticleExchange ex(MPI_COMM_WORLD, mesh);
    OwnedParticles owned;
    // Several coupling steps with moving particles: buffers are reused and
    // consecutive NBX rounds follow each other closely.
    for (int step = 0; step < 4; ++step) {
        INFO("rank " << rank << " of " << size << ", step " << step);
        const auto dem = demParticles(rank, size, step);
        ex.forward(dem, owned);

        // The half-open BoxMesh gives every point of the box to exactly one slab.
        int unowned = 0;
        for (const auto& p : dem) unowned += lowestFinder(meshes, p.x) < 0;
        CHECK(unowned == 0);
        // Exactly the expected particles, in (source rank, dem index) order,
        // with their state copied bit for bit and the cell of this rank's mesh.
        CHECK(countMismatches(owned, expectedOwned(meshes, rank, step)) == 0);
        CHECK(globalSum(static_cast<long>(owned.size())) == globalSum(static_cast<long>(dem.size())));
        // Records to several candidates were sent: the face particles are in
        // both neighbours' (inflated) boxes.
        const long sent = globalSum(ex.stats().particlesSent);
        if (size > 1) CHECK(sent > globalSum(static_cast<long>(dem.size())));
        CHECK(ex.stats().partners <= size - 1);

        // backward(): id, position and the owning rank go home.
        CHECK(backwardMismatches(ex, owned, dem, meshes) == 0);
    }
}

TEST_CASE("drag forces go home once each and conserve momentum to round-off", "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    std::vector<BoxMesh> slabs;
    for (int p = 0; p < size; ++p) slabs.push_back(cfdSlab(p, size));
    std::vector<const CellLocator*> meshes;
    for (const auto& s : slabs) meshes.push_back(&s);
    const BoxMesh& mesh = slabs[rank];

    ParticleExchange ex(MPI_COMM_WORLD, mesh);
    const auto dem = demParticles(rank, size, 1);
    OwnedParticles owned;
    ex.forward(dem, owned);

    // CFD side: force on each particle, minus the force into its cell's
    // momentum source.
    std::vector<double> forces;
    std::vector<Vec3> fluidSource(mesh.nCells(), Vec3::Zero());
    Vec3 magnitude = Vec3::Zero();  // sum of |F_i| per component: the round-off scale
    for (const auto& o : owned) {
        const Vec3 f = dragForce(o.state, mesh.cellCentre(o.cell));
        for (int a = 0; a < 3; ++a) forces.push_back(f[a]);
        fluidSource[o.cell] -= f;
        magnitude += f.cwiseAbs();
    }
    std::vector<double> out;
    ex.backward(forces, 3, out);
    REQUIRE(out.size() == 3 * dem.size());

    // DEM side: each particle got ITS force (recomputed directly from the
    // cell that owns it). Same expression, same inputs: equal up to the
    // last bits (4 ulp-scale slack in case the compiler fuses differently).
    Vec3 onParticles = Vec3::Zero();
    int wrong = 0;
    for (std::size_t i = 0; i < dem.size(); ++i) {
        const int owner = lowestFinder(meshes, dem[i].x);
        const Vec3 want = dragForce(dem[i], slabs[owner].cellCentre(slabs[owner].findCell(dem[i].x)));
        const Vec3 got(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
        wrong += !((got - want).norm() <= 1e-15 * want.norm());
        onParticles += got;
    }
    CHECK(wrong == 0);

    // Global momentum balance: sum of particle forces = - sum of fluid
    // sources, to round-off. Both are sums of the same ~N terms in different
    // orders, so they differ by O(N eps max|F_i|) <= 1e-12 * sum |F_i| for
    // N ~ 1e4 (eps = 2.2e-16).
    Vec3 onFluid = Vec3::Zero();
    for (const Vec3& s : fluidSource) onFluid += s;
    double local[9], global[9];
    for (int a = 0; a < 3; ++a) {
        local[a] = onParticles[a];
        local[3 + a] = onFluid[a];
        local[6 + a] = magnitude[a];
    }
    MPI_Allreduce(local, global, 9, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    for (int a = 0; a < 3; ++a) {
        INFO("component " << a << ": particles " << global[a] << ", fluid " << global[3 + a]);
        CHECK(global[6 + a] > 0);
        CHECK(std::abs(global[a] + global[3 + a]) <= 1e-12 * global[6 + a]);
    }
    // The x force is dominated by the mean air speed 1 + z > 0: a real,
    // non-cancelling sum, so the relative check above is meaningful.
    CHECK(global[0] > 0.5 * global[6]);
}

TEST_CASE("a point found by two ranks (closed cells) is owned once, by the lower rank", "[exchange][mpi]") {
    const int rank = worldRank(), size = worldSize();
    std::vector<ClosedSlab> slabs;
    for (int p = 0; p < size; ++p) slabs.emplace_back(p, size);
    std::vector<const CellLocator*> meshes;
    for (const auto& s : slabs) meshes.push_back(&s);

    // The ties are real: with closed cells, the points on the faces between
    // slabs are found by two ranks.
    const auto dem = demParticles(rank, size, 0);
    long ties = 0;
    for (const auto& p : dem) {
        int finders = 0;
        for (const auto* m : meshes) finders += m->findCell(p.x) >= 0;
        ties += finders > 1;
    }
    // Every rank holds 10 particles on each of the size-1 internal faces, and
    // rank 0 one more (a corner on the first face); random points never land
    // exactly on a face.
    if (size > 1) CHECK(globalSum(ties) == 10 * size * (size - 1) + 1);

    ParticleExchange ex(MPI_COMM_WORLD, slabs[rank]);
    OwnedParticles owned;
    ex.forward(dem, owned);
    // expectedOwned gives each particle to its LOWEST finder.
    CHECK(countMismatches(owned, expectedOwned(meshes, rank, 0)) == 0);
    CHECK(globalSum(static_cast<long>(owned.size())) == globalSum(static_cast<long>(dem.size())));

    std::vector<double> ids, out;
    for (const auto& o : owned) ids.push_back(static_cast<double>(o.state.id));
    ex.backward(ids, 1, out);
    int wrong = 0;
    for (std::size_t i = 0; i < dem.size(); ++i) wrong += out[i] != static_cast<double>(dem[i].id);
    CHECK(wrong == 0);
}
