// GaussianVoidFraction.hpp: a smoothed, volume-conserving void-fraction model ("gaussian").
//
// Summary: a particle's volume is spread over the cells around it with a
// truncated Gaussian kernel, renormalised over the cells actually used.
//
// Stencil: over the set S of local cells whose centres x_c lie within
// R_c = cutoff * width of the particle centre x_p (plus, always, the centre
// cell), the weight of cell c is
//     w_c = g_c V_c / sum_{c' in S} g_c' V_c',   g_c = exp(-|x_c - x_p|^2 / (2 width^2)).
// So sum_c w_c = 1 exactly up to round-off, and the solid volume w_c V_p put in
// cell c is V_p times the kernel's share of that cell: total solid volume is
// conserved by construction. S is found by a breadth-first search over
// mesh.cellNeighbours() from the centre cell; a cell beyond R_c is neither
// used nor expanded (on a structured mesh this finds every cell centre in the
// ball). The centre cell is always in S and always expanded, so S is never
// empty. For numerical safety g is evaluated relative to the nearest cell
// centre, which cancels in the normalisation.
//
// Truncation and parallel runs: the kernel is cut at the wall and at this
// rank's mesh boundary (cellNeighbours() gives local cells only) and then
// renormalised over what is left. Volume stays on the rank and is conserved,
// but near a processor boundary the split differs from a serial run, so
// results depend (slightly) on the decomposition. `centre` is the model that
// is exactly independent of it. Near a wall the truncated kernel's centroid
// moves inwards, away from the particle centre.
//
// Validity: any ratio of cell size to particle size; with cells much larger
// than width the stencil is just the centre cell. The kernel's first moment
// equals x_p (far from boundaries) up to the truncation tail, whose share of
// the first moment is at most sqrt(2/pi) (c^2 + 2) exp(-c^2/2) width
// (0.10 width for c = 3, 8e-5 width for c = 5), plus the lattice sampling
// error, exponentially small once width >~ cell size.
//
// Parameters:
//   width    kernel standard deviation per axis [m], required, > 0. A
//            diffusion-based smoothing (Sun & Xiao) with unit diffusivity run
//            for a pseudo-time T corresponds to width = sqrt(2 T).
//   cutoff   truncation radius in widths [-], 1 <= cutoff <= 10, default 3.
//            Cost grows as (cutoff * width / cell size)^3 cells per particle:
//            on a BoxMesh roughly 70 ns per stencil cell through the
//            locator's virtual calls (measured before the search read the flat
//            CellLocator::cellArrays), i.e. 7-16 us per particle for width =
//            cell size (106 cells) and 45-85 us for width = 2 cell sizes (790
//            cells), so keep width near the cell size. On the wedge-silo demo
//            (5.6 cells per stencil) the whole void fraction + mapping stage
//            costs 246 ns per parcel and coupling step with the flat arrays
//            (339 ns before; bench/results/mapping-exchange-cpu.md).
//
// References: the Gaussian kernel of the statistical kernel method, as
// analysed by Sun, R., Xiao, H. (2015), Diffusion-based coarse graining in
// hybrid continuum-discrete solvers: theoretical formulation and a priori
// tests, Int. J. Multiphase Flow 77:142-157 (arXiv:1409.0001), and applied in
// Sun, R., Xiao, H. (2015), ... Applications in CFD-DEM, Int. J. Multiphase
// Flow 72:233-247; weighting functions for averaging DEM data: Zhu, H.P.,
// Zhou, Z.Y., Yang, R.Y., Yu, A.B. (2007), Discrete particle simulation of
// particulate systems: theoretical developments, Chem. Eng. Sci. 62:3378-3396.
// The discrete renormalisation over the cells used is our choice (it makes
// conservation exact on any mesh and at any boundary).
#pragma once
#include <cstdint>

#include "core/Dictionary.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

class GaussianVoidFraction : public VoidFractionModel {
public:
    static constexpr const char* typeName = "gaussian";
    static constexpr double defaultCutoff = 3.0;
    static constexpr double minCutoff = 1.0;
    static constexpr double maxCutoff = 10.0;

    // Throws ParameterError (core/Registry.hpp) naming `width` or `cutoff`.
    GaussianVoidFraction(double width, double cutoff = defaultCutoff);
    // Reads `width` (required) and `cutoff` (optional); through the registry
    // a missing, non-finite or out-of-range value names the file and key.
    static std::unique_ptr<VoidFractionModel> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    // Not thread-safe: reuses the search buffers below (one model per thread).
    void stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                 std::vector<CellWeight>& out) const override;

    double width() const { return width_; }
    double cutoff() const { return cutoff_; }

private:
    double width_, cutoff_;
    // Breadth-first search workspace, reused across particles: a visit stamp
    // per cell (stamp_[c] == generation_ means visited for this particle; the
    // stencil being built is the queue).
    mutable std::vector<std::uint32_t> stamp_;
    mutable std::uint32_t generation_ = 0;
};

}  // namespace granair
