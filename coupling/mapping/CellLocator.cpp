// CellLocator.cpp: the default flat cell arrays (see CellLocator.hpp).
#include "mapping/CellLocator.hpp"

#include "core/CapacityBytes.hpp"

namespace granair {

const CellArrays& CellLocator::cellArrays() const {
    if (!cache_.copy) {
        auto a = std::make_unique<ArrayCopy>();
        const int n = nCells();
        a->centres.resize(3 * static_cast<std::size_t>(n));
        a->volumes.resize(static_cast<std::size_t>(n));
        a->start.assign(1, 0);
        a->start.reserve(static_cast<std::size_t>(n) + 1);
        std::vector<int> nb;
        for (int c = 0; c < n; ++c) {
            const Vec3 x = cellCentre(c);
            for (int k = 0; k < 3; ++k) a->centres[3 * static_cast<std::size_t>(c) + k] = x[k];
            a->volumes[static_cast<std::size_t>(c)] = cellVolume(c);
            cellNeighbours(c, nb);
            a->neighbours.insert(a->neighbours.end(), nb.begin(), nb.end());
            a->start.push_back(static_cast<int>(a->neighbours.size()));
        }
        a->view = {a->centres.data(), a->volumes.data(), a->start.data(), a->neighbours.data()};
        cache_.copy = std::move(a);
    }
    return cache_.copy->view;
}

std::size_t CellLocator::cellArrayBytes() const {
    if (!cache_.copy) return 0;
    const ArrayCopy& a = *cache_.copy;
    return capacityBytes(a.centres) + capacityBytes(a.volumes) + capacityBytes(a.start) +
           capacityBytes(a.neighbours);
}

}  // namespace granair
