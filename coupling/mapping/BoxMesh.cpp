// BoxMesh.cpp: see BoxMesh.hpp.
#include "mapping/BoxMesh.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace granair {

BoxMesh::BoxMesh(const Vec3& lo, const Vec3& hi, const Index3& n) : BoxMesh(lo, hi, n, {0, 0, 0}, n) {}

BoxMesh::BoxMesh(const Vec3& lo, const Vec3& hi, const Index3& n, const Index3& ownedLo,
                 const Index3& ownedHi)
    : lo_(lo), hi_(hi), n_(n), ownedLo_(ownedLo), ownedHi_(ownedHi) {
    for (int a = 0; a < 3; ++a) {
        if (n[a] < 1 || !(hi[a] > lo[a])) fail<InputError>("BoxMesh: need n >= 1 and hi > lo on axis ", a);
        if (ownedLo[a] < 0 || ownedHi[a] > n[a] || ownedLo[a] > ownedHi[a])
            fail<InputError>("BoxMesh: owned block out of range on axis ", a);
        h_[a] = (hi[a] - lo[a]) / n[a];
        m_[a] = ownedHi[a] - ownedLo[a];
    }
}

BoxMesh BoxMesh::slab(const Vec3& lo, const Vec3& hi, const Index3& n, int nParts, int part, int axis) {
    Index3 a{0, 0, 0}, b = n;
    a[axis] = static_cast<int>(static_cast<long>(n[axis]) * part / nParts);
    b[axis] = static_cast<int>(static_cast<long>(n[axis]) * (part + 1) / nParts);
    return BoxMesh(lo, hi, n, a, b);
}

int BoxMesh::nCells() const { return m_[0] * m_[1] * m_[2]; }

int BoxMesh::findCell(const Vec3& x, int) const {
    Index3 ijk;
    for (int a = 0; a < 3; ++a) {
        if (!(x[a] >= lo_[a] && x[a] <= hi_[a])) return -1;  // also rejects NaN
        int i = static_cast<int>(std::floor((x[a] - lo_[a]) / h_[a]));
        if (i >= n_[a]) i = n_[a] - 1;  // x == hi
        ijk[a] = i;
    }
    return localCell(ijk);
}

double BoxMesh::cellVolume(int) const { return h_.prod(); }

BoxMesh::Index3 BoxMesh::globalIjk(int cell) const {
    const int i = cell % m_[0];
    const int j = (cell / m_[0]) % m_[1];
    const int k = cell / (m_[0] * m_[1]);
    return {ownedLo_[0] + i, ownedLo_[1] + j, ownedLo_[2] + k};
}

int BoxMesh::localCell(const Index3& g) const {
    for (int a = 0; a < 3; ++a)
        if (g[a] < ownedLo_[a] || g[a] >= ownedHi_[a]) return -1;
    return (g[0] - ownedLo_[0]) + m_[0] * ((g[1] - ownedLo_[1]) + m_[1] * (g[2] - ownedLo_[2]));
}

long BoxMesh::globalIndex(int cell) const {
    const Index3 g = globalIjk(cell);
    return g[0] + static_cast<long>(n_[0]) * (g[1] + static_cast<long>(n_[1]) * g[2]);
}

Vec3 BoxMesh::cellCentre(int cell) const {
    const Index3 g = globalIjk(cell);
    return lo_ + Vec3((g[0] + 0.5) * h_[0], (g[1] + 0.5) * h_[1], (g[2] + 0.5) * h_[2]);
}

void BoxMesh::cellNeighbours(int cell, std::vector<int>& out) const {
    out.clear();
    const Index3 g = globalIjk(cell);
    for (int a = 0; a < 3; ++a)
        for (int d : {-1, 1}) {
            Index3 q = g;
            q[a] += d;
            const int c = localCell(q);
            if (c >= 0) out.push_back(c);
        }
}

Box BoxMesh::bounds() const {
    Box b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = lo_[a] + ownedLo_[a] * h_[a];
        b.hi[a] = ownedHi_[a] == n_[a] ? hi_[a] : lo_[a] + ownedHi_[a] * h_[a];
    }
    if (nCells() == 0) return Box{};
    return b;
}

}  // namespace granair
