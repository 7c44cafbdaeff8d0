// VoidFractionModel.hpp: how a particle's volume is spread over cells.
//
// A model turns one particle (centre cell known) into a stencil of
// (local cell, weight) pairs whose weights sum to 1. The same stencil is used
// for everything a particle gives to or takes from the cells: solid volume,
// drag coefficient, particle velocity, and the air velocity and void fraction
// the particle sees. Using one stencil both ways is what makes the momentum
// given to the air equal and opposite to the drag on the particles, and
// makes total solid volume conserved by construction.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/Particle.hpp"
#include "core/Registry.hpp"
#include "mapping/CellLocator.hpp"

namespace granair {

struct CellWeight {
    int cell;
    double weight;
};

class VoidFractionModel {
public:
    virtual ~VoidFractionModel() = default;
    virtual std::string name() const = 0;

    // Append the stencil of particle p (inside local cell `centreCell`) to out
    // (out is cleared first). Weights are >= 0 and sum to 1 to round-off. The
    // first entry is centreCell (the coupling step stores no cell index for
    // it: coupler/CouplingStep.hpp), no cell appears twice.
    virtual void stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                         std::vector<CellWeight>& out) const = 0;

    // True when every stencil is {centreCell, 1} (`centre`): the coupling
    // step then keeps no stencils (owned.cell(p) with weight 1 is the same).
    virtual bool centreCellOnly() const { return false; }
};

// The registry of void-fraction models (registerVoidFractionModels.cpp),
// filled on first use from the list in voidfraction/sources.cmake.
const Registry<VoidFractionModel>& voidFractionModels();

}  // namespace granair
