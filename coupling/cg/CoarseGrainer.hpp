// CoarseGrainer.hpp: the snapshot loop: particles and contacts -> CG fields on a grid.
//
// Cost scales with particles + contacts: each object visits only the grid
// points within the kernel cutoff of it (its index range on the regular
// grid, no search), so one snapshot costs ~ (objects) x (points per cutoff
// ball or capsule) kernel evaluations.
//
// Parallel: OpenMP threads own slabs of the grid along its slowest axis (z,
// or y, or x); a thread visits every object whose index range reaches its
// slab and writes only its own points. No atomics, no per-thread copies of
// the fields, and every grid point sums its contributions in the same order
// whatever the thread count, so the result is bitwise independent of it.
//
// Periodic directions (from the dump's box): objects near a periodic
// boundary are also deposited at their images shifted by one period, so
// fields wrap across it; a pair's branch vector is the minimum image.
//
// RZ: the 3-D kernel averaged over the azimuth of each ring (Gauss-Legendre
// in the angle: `azimuthalNodes` nodes over the kernel's angular support for
// particles, exact to round-off; composite rules for contact segments, whose
// accuracy the tests state).
#pragma once
#include <array>
#include <vector>

#include "cg/CgGrid.hpp"
#include "cg/CgKernel.hpp"
#include "cg/CgRawFields.hpp"
#include "cg/CgSnapshot.hpp"

namespace granair {

struct CgCounts {
    std::size_t particles = 0, pairs = 0, walls = 0;  // deposited (images included)
};

class CoarseGrainer {
public:
    // kernel.dims() must equal grid.kernelDims().
    CoarseGrainer(CgGrid grid, CgKernel kernel, int azimuthalNodes = 16);

    const CgGrid& grid() const { return grid_; }
    const CgKernel& kernel() const { return kernel_; }

    // Raw fields of one snapshot on the grid. threads <= 0: OpenMP's default.
    CgRawFields compute(const CgSnapshot& snap, int threads = 0, CgCounts* counts = nullptr) const;

    // The same fields at arbitrary points (Cartesian: x, y, z with the
    // averaged components ignored; RZ: (r, ignored, z)), by brute force over
    // every object. For tests and a few probe points.
    CgRawFields evaluateAt(const std::vector<Vec3>& points, const CgSnapshot& snap) const;

    struct Copy;      // an object or one of its periodic images, with its grid index range
    struct Prepared;  // a copy's point-independent terms

private:
    // gridOnly: drop copies whose cutoff reaches no grid point.
    std::vector<Copy> copies(const CgSnapshot& snap, bool gridOnly) const;
    Prepared prepare(const Copy& c, const CgSnapshot& snap) const;
    void deposit(const Copy& c, const CgSnapshot& snap, int slabLo, int slabHi, CgRawFields& out) const;
    void apply(const Prepared& p, const Vec3& point, double* rec) const;

    CgGrid grid_;
    CgKernel kernel_;
    int azimuthalNodes_;
    int slabAxis_;
    std::array<bool, 3> resolved_;
};

}  // namespace granair
