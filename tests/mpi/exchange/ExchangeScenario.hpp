// ExchangeScenario.hpp: the decompositions and particle sets of the MPI
// exchange tests, and the direct (non-MPI) computation they are checked against.
//
// Box [0,1] x [0,0.8] x [0,1.2] with 10 x 8 x 12 cells. The CFD decomposition
// is BoxMesh::slab along z; the DEM decomposition is slabs along x (so every
// DEM rank talks to every CFD rank). Each DEM rank holds random particles of
// its x slab, 1 in 20 placed anywhere in the box ("drifted" particles that
// belong to another DEM slab), and particles exactly on every z face between
// CFD slabs and on the box's bottom and top. Particles get id
// src * kIdStride + index, so sorting by id is sorting by (source rank,
// position in the source's dem vector). Everything is a pure function of
// (source rank, rank count, step): any rank can rebuild any rank's particles,
// which is what the checks do (test-only global data).
#pragma once
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "core/Particle.hpp"
#include "exchange/ParticleExchange.hpp"
#include "mapping/BoxMesh.hpp"

namespace scenario {

using granair::BoxMesh;
using granair::CellLocator;
using granair::OwnedParticle;
using granair::ParticleState;
using granair::Vec3;

const Vec3 kLo(0, 0, 0), kHi(1.0, 0.8, 1.2);
const BoxMesh::Index3 kCells{10, 8, 12};
constexpr int kCfdAxis = 2;  // CFD slabs along z
constexpr int kDemAxis = 0;  // DEM slabs along x
constexpr std::int64_t kIdStride = 1000000;
constexpr double kDt = 0.01;  // [s] step of the particle motion between coupling steps

inline int worldRank() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}
inline int worldSize() {
    int s = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
}

inline BoxMesh cfdSlab(int part, int parts) { return BoxMesh::slab(kLo, kHi, kCells, parts, part, kCfdAxis); }

// z of the faces between CFD slabs, computed exactly as BoxMesh::bounds()
// computes the slab ends (so these points are in both neighbours' boxes).
inline std::vector<double> cfdFaces(int parts) {
    std::vector<double> z;
    for (int p = 1; p < parts; ++p) z.push_back(cfdSlab(p, parts).bounds().lo[kCfdAxis]);
    return z;
}

inline double reflectInto(double x, double lo, double hi) {
    if (x < lo) return 2 * lo - x;
    if (x > hi) return 2 * hi - x;
    return x;
}

// The DEM particles of rank `src` at coupling step `step`.
inline std::vector<ParticleState> demParticles(int src, int parts, int step, int nRandom = 2000) {
    std::mt19937_64 rng(1000 + src);
    std::uniform_real_distribution<double> u(0, 1);
    const double xLo = kLo[kDemAxis] + (kHi[kDemAxis] - kLo[kDemAxis]) * src / parts;
    const double xHi = kLo[kDemAxis] + (kHi[kDemAxis] - kLo[kDemAxis]) * (src + 1) / parts;
    std::vector<ParticleState> ps;
    auto add = [&](const Vec3& x, bool moves) {
        ParticleState p;
        p.id = src * kIdStride + static_cast<std::int64_t>(ps.size());
        for (int a = 0; a < 3; ++a) p.v[a] = u(rng) - 0.5;
        p.radius = 1e-3 * (0.5 + u(rng));
        p.x = x;
        if (moves)
            for (int a = 0; a < 3; ++a) p.x[a] = reflectInto(x[a] + p.v[a] * kDt * step, kLo[a], kHi[a]);
        ps.push_back(p);
    };
    for (int i = 0; i < nRandom; ++i) {
        Vec3 x;
        for (int a = 0; a < 3; ++a) x[a] = kLo[a] + u(rng) * (kHi[a] - kLo[a]);
        if (i % 20 != 7) x[kDemAxis] = xLo + u(rng) * (xHi - xLo);  // in this DEM slab
        add(x, true);
    }
    // Exactly on the CFD slab faces, and on the bottom and top of the box.
    std::vector<double> faces = cfdFaces(parts);
    faces.push_back(kLo[kCfdAxis]);
    faces.push_back(kHi[kCfdAxis]);
    for (double z : faces)
        for (int i = 0; i < 10; ++i) {
            Vec3 x(xLo + u(rng) * (xHi - xLo), kLo[1] + u(rng) * (kHi[1] - kLo[1]), z);
            add(x, false);
        }
    if (src == 0) {
        add(kLo, false);
        add(kHi, false);
        add(Vec3(kHi[0], kLo[1], cfdFaces(parts).empty() ? kHi[2] : cfdFaces(parts)[0]), false);
    }
    return ps;
}

// The lowest rank whose locator finds x, or -1.
inline int lowestFinder(const std::vector<const CellLocator*>& meshes, const Vec3& x) {
    for (int p = 0; p < static_cast<int>(meshes.size()); ++p)
        if (meshes[p]->findCell(x) >= 0) return p;
    return -1;
}

// What `rank` must own after forward() at `step`, computed directly: every
// source rank in order, its particles in dem order, those whose lowest
// finder is `rank`.
inline std::vector<OwnedParticle> expectedOwned(const std::vector<const CellLocator*>& meshes, int rank,
                                                int step) {
    const int parts = static_cast<int>(meshes.size());
    std::vector<OwnedParticle> out;
    for (int src = 0; src < parts; ++src)
        for (const ParticleState& p : demParticles(src, parts, step))
            if (lowestFinder(meshes, p.x) == rank) out.push_back({p, meshes[rank]->findCell(p.x)});
    return out;
}

// Number of mismatches between two owned lists (ids, states bit for bit, cells).
inline int countMismatches(const granair::OwnedParticles& got, const std::vector<OwnedParticle>& want) {
    int bad = static_cast<int>(std::max(got.size(), want.size()) - std::min(got.size(), want.size()));
    for (std::size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
        const ParticleState &a = got.state(i), &b = want[i].state;
        bad += !(a.id == b.id && a.x == b.x && a.v == b.v && a.radius == b.radius &&
                 got.cell(i) == want[i].cell);
    }
    return bad;
}

// A test-only locator with CLOSED cells: a point on the boundary between two
// ranks' blocks is found by BOTH (as can happen in a general mesh where each
// rank's point-in-cell test has its own round-off). Otherwise the BoxMesh
// block it wraps (meshLo: the lower corner of the whole mesh).
class ClosedCells : public CellLocator {
public:
    ClosedCells(BoxMesh inner, const Vec3& meshLo) : inner_(std::move(inner)), meshLo_(meshLo) {}
    int nCells() const override { return inner_.nCells(); }
    int findCell(const Vec3& x, int hint = -1) const override {
        const int c = inner_.findCell(x, hint);
        if (c >= 0 || inner_.nCells() == 0 || !inner_.bounds().contains(x)) return c;
        // On the block's closed boundary but given to the neighbour by the
        // half-open rule: take the nearest own cell.
        const BoxMesh::Index3 first = inner_.globalIjk(0), last = inner_.globalIjk(inner_.nCells() - 1);
        BoxMesh::Index3 ijk;
        for (int a = 0; a < 3; ++a) {
            const int i = static_cast<int>(std::floor((x[a] - meshLo_[a]) / inner_.spacing()[a]));
            ijk[a] = std::clamp(i, first[a], last[a]);
        }
        return inner_.localCell(ijk);
    }
    double cellVolume(int cell) const override { return inner_.cellVolume(cell); }
    Vec3 cellCentre(int cell) const override { return inner_.cellCentre(cell); }
    void cellNeighbours(int cell, std::vector<int>& out) const override { inner_.cellNeighbours(cell, out); }
    granair::Box bounds() const override { return inner_.bounds(); }

private:
    BoxMesh inner_;
    Vec3 meshLo_;
};

// The CFD slabs of the scenario with closed cells.
class ClosedSlab : public ClosedCells {
public:
    ClosedSlab(int part, int parts) : ClosedCells(cfdSlab(part, parts), kLo) {}
};

// backward() of (id, x, owner rank) per owned particle: the number of dem
// particles of this rank whose values did not come home intact from their
// lowest finder (0 when every value is back, once: out is NaN-filled).
inline int backwardMismatches(granair::ParticleExchange& ex, const granair::OwnedParticles& owned,
                              const std::vector<ParticleState>& dem,
                              const std::vector<const CellLocator*>& meshes) {
    const int width = 5;
    std::vector<double> values, out;
    for (std::size_t k = 0; k < owned.size(); ++k) {
        values.push_back(static_cast<double>(owned.state(k).id));  // ids < 2^53: exact
        for (int a = 0; a < 3; ++a) values.push_back(owned.state(k).x[a]);
        values.push_back(worldRank());
    }
    ex.backward(values, width, out);
    if (out.size() != dem.size() * width) return static_cast<int>(dem.size());
    int wrong = 0;
    for (std::size_t i = 0; i < dem.size(); ++i) {
        wrong += out[i * width] != static_cast<double>(dem[i].id);
        for (int a = 0; a < 3; ++a) wrong += out[i * width + 1 + a] != dem[i].x[a];
        wrong += out[i * width + 4] != lowestFinder(meshes, dem[i].x);
    }
    // The same values through a sink (backwardFill with no output array, as
    // the coupled run hands forces to LIGGGHTS): each dem particle once, the
    // same numbers bit for bit.
    std::vector<double> sunk(out.size(), 0.0);
    std::vector<int> calls(dem.size(), 0);
    ex.backwardFill(
        width, [&](std::size_t k, double* dst) { std::copy_n(values.data() + k * width, width, dst); },
        [&](std::size_t i, const double* v) {
            ++calls[i];
            std::copy_n(v, width, sunk.data() + i * width);
        });
    ex.backwardSend();
    for (std::size_t i = 0; i < dem.size(); ++i) wrong += calls[i] != 1;
    for (std::size_t j = 0; j < out.size(); ++j) wrong += sunk[j] != out[j];
    return wrong;
}

// Sum of an int over MPI_COMM_WORLD.
inline long globalSum(long local) {
    long total = 0;
    MPI_Allreduce(&local, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    return total;
}

}  // namespace scenario
