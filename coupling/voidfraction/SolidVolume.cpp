// SolidVolume.cpp: see SolidVolume.hpp.
#include "voidfraction/SolidVolume.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace granair {

void accumulateSolidVolume(const CellLocator& mesh, const VoidFractionModel& model,
                           const std::vector<ParticleState>& particles, const std::vector<int>& cells,
                           std::vector<double>& solidVolume) {
    const int nCells = mesh.nCells();
    if (particles.size() != cells.size())
        fail("accumulateSolidVolume: ", particles.size(), " particles but ", cells.size(), " centre cells");
    if (solidVolume.empty()) solidVolume.assign(static_cast<std::size_t>(nCells), 0.0);
    if (solidVolume.size() != static_cast<std::size_t>(nCells))
        fail("accumulateSolidVolume: solidVolume has ", solidVolume.size(), " entries, the mesh ", nCells,
             " cells");

    std::vector<CellWeight> st;  // reused for every particle: one allocation per call
    st.reserve(64);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const ParticleState& p = particles[i];
        const int c = cells[i];
        if (c < 0 || c >= nCells)
            fail<InputError>("particle ", p.id, " at (", p.x.x(), ", ", p.x.y(), ", ", p.x.z(),
                             "): centre cell ", c, " is not a local cell (expected 0 <= cell < ", nCells,
                             ")");
        if (!(p.radius >= 0) || !std::isfinite(p.radius))
            fail<InputError>("particle ", p.id, ": radius ", p.radius,
                             " invalid, expected a finite radius >= 0");
        const double vp = sphereVolume(p.radius);
        model.stencil(mesh, p, c, st);
        for (const CellWeight& cw : st) solidVolume[static_cast<std::size_t>(cw.cell)] += cw.weight * vp;
    }
}

}  // namespace granair
