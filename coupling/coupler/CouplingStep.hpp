// CouplingStep.hpp: what the particles give the air and the air gives back,
// on the rank that owns the particles' cells.
//
// One coupling step, after the exchange has brought each particle to the
// rank owning its cell (exchange/ParticleExchange):
//   1. particlesToCells(): each particle's stencil (voidfraction model) ->
//      solid volume per cell -> void fraction eps (floored); drag
//      coefficient beta per particle (drag law, at the air velocity of the
//      previous step and the new eps); per cell
//          K  = sum_p w_pc beta_p / V_c                      [kg/(m3 s)]
//          Us = sum_p w_pc beta_p v_p / sum_p w_pc beta_p     [m/s]
//   2. the air solver advances with K implicit (cfd-side).
//   3. cellsToParticles(): force on each particle
//          F_p = beta_p (U_f,p - v_p) - V_p grad(p)_p - V_p rho_f g
//      with U_f,p = sum_c w_pc U_c and grad(p)_p = sum_c w_pc grad(p)_c.
// Because the same weights w_pc carry K/Us to the cells and the air velocity
// back, sum_p drag_p = sum_c K_c V_c (U_c - Us_c): the momentum the air
// loses is exactly the drag the particles gain.
//
// Parcels (coarse-graining factor s) hold s^3 primary particles of diameter
// 2 radius / s; beta is s^3 times the primary one (drag/DragLaw.hpp).
// Cell arrays are plain contiguous doubles (3 per cell for vectors), so the
// cfd-side can pass OpenFOAM's field storage without copies.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "coupler/CouplingSettings.hpp"
#include "exchange/ParticleExchange.hpp"
#include "mapping/CellLocator.hpp"

namespace granair {

struct CouplingStepStats {
    std::int64_t floorHits = 0;       // cells floored in the last step (this rank)
    double minRawVoidFraction = 1.0;  // smallest eps before flooring, last step (this rank)
};

class CouplingStep {
public:
    // Needs settings.voidFraction; settings.drag only for particlesToCells
    // (a DEM-only run maps the void fraction alone, for its output).
    CouplingStep(const CouplingSettings& settings, const CellLocator& mesh, FluidProperties fluid);

    // The first half of step 1: stencils, solid volume and the (floored)
    // void fraction eps of every local cell (1 per cell); updates stats().
    void voidFraction(const OwnedParticles& owned, double* eps);

    // Step 1. Ucell: air velocity per local cell (3 doubles each) from the
    // previous air step. Writes eps, K (1 per cell) and Us (3 per cell).
    void particlesToCells(const OwnedParticles& owned, const double* Ucell,
                          double* eps, double* K, double* Us);

    // Step 3. `owned` as given to particlesToCells; Ucell, gradPcell: new air
    // velocity and pressure gradient [Pa/m] per cell. Writes 3 doubles per
    // owned particle (same order) into forces, and the drag part alone into
    // *drag when given (tests, output).
    void cellsToParticles(const OwnedParticles& owned, const double* Ucell,
                          const double* gradPcell, std::vector<double>& forces,
                          std::vector<double>* drag = nullptr) const;

    // Step 3 one particle at a time, for a caller that puts each force
    // straight where it goes (ParticleExchange::backwardFill: no array of
    // owned forces in between). forces(...)(p, f) writes the force on owned
    // particle p to f[0..2], exactly as cellsToParticles does.
    class Forces {
    public:
        void operator()(std::size_t p, double* f, double* drag = nullptr) const;

    private:
        friend class CouplingStep;
        Forces(const CouplingStep& step, const OwnedParticles& owned, const double* Ucell, const double* gradPcell)
            : step_(step), owned_(owned), U_(Ucell), gradP_(gradPcell),
              buoyancyPerVolume_(-step.fluid_.rho * step.settings_.gravity) {}
        const CouplingStep& step_;
        const OwnedParticles& owned_;
        const double* U_;
        const double* gradP_;
        Vec3 buoyancyPerVolume_;
    };
    // Checks that `owned` is the list of the last particlesToCells.
    Forces forces(const OwnedParticles& owned, const double* Ucell, const double* gradPcell) const;

    const CouplingStepStats& stats() const { return stats_; }

    // Bytes held by this object's buffers (vector capacities, i.e. their high
    // water mark): per-particle ones and per-cell ones, for the memory report.
    std::size_t particleBufferBytes() const;
    std::size_t cellBufferBytes() const;
    // The stencils' cells are kept as plain indices (a stencil on this rank
    // spanned more than 16 bits of cell numbers; see the members below).
    bool wideStencilCells() const { return wideCells_; }

private:
    const CouplingSettings& settings_;
    const CellLocator& mesh_;
    FluidProperties fluid_;
    // Stencils of the particles of the last step, CSR layout (an array of
    // CellWeight would pad each 12-byte pair to 16): particle p's weights are
    // stencilWeight_[offset_[p] .. offset_[p+1]), the first one the centre
    // cell's (owned.cell(p), the models' contract: no cell stored for it).
    // The cells of the others, entry k > offset_[p] (one centre entry omitted
    // per particle before it: index k - p - 1), as their difference from the
    // centre cell in 16 bits (stencilDelta_; the cells of a stencil are
    // close in a mesh's numbering, OpenFOAM's renumberMesh keeps them so), or,
    // from the first stencil on this rank with a difference beyond 16 bits
    // on, as plain cell indices (stencilCell_, wideCells_). Memory: 8 bytes
    // per stencil entry and 2 (or 4) per entry beyond the centre, instead of
    // 12 per entry: the largest per-particle buffers of a smoothing model.
    // None for a model whose stencil is always the centre cell alone
    // (`centre`): weight 1 there.
    bool centreOnly_;
    bool wideCells_ = false;
    std::vector<std::uint32_t> offset_;
    std::vector<std::int16_t> stencilDelta_;
    std::vector<int> stencilCell_;
    std::vector<double> stencilWeight_;
    // Stencils of `owned` into the arrays above and their solid volume into
    // solid_ (zeroed first); false if a cell difference does not fit 16 bits
    // (wideCells_ off): call again with wideCells_ on.
    bool buildStencils(const OwnedParticles& owned);
    // Calls f(cell, weight) for each stencil entry of owned particle p.
    template <class F>
    void forEachWeight(const OwnedParticles& owned, std::size_t p, F&& f) const {
        const int centre = owned.cell(p);
        if (centreOnly_) {
            f(centre, 1.0);
            return;
        }
        const std::size_t first = offset_[p], end = offset_[p + 1];
        f(centre, stencilWeight_[first]);
        // offset_[p] >= p (every stencil has its centre entry): k - p - 1 >= 0.
        if (wideCells_)
            for (std::size_t k = first + 1; k < end; ++k) f(stencilCell_[k - p - 1], stencilWeight_[k]);
        else
            for (std::size_t k = first + 1; k < end; ++k) f(centre + stencilDelta_[k - p - 1], stencilWeight_[k]);
    }
    std::vector<double> beta_;     // per particle [kg/s]
    std::vector<double> solid_;    // per cell, workspace
    std::vector<double> sumBeta_;  // per cell, workspace
    std::vector<CellWeight> scratch_;
    CouplingStepStats stats_;
};

}  // namespace granair
