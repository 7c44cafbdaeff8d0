// LumpedVoidFraction.cpp: see LumpedVoidFraction.hpp.
#include "voidfraction/LumpedVoidFraction.hpp"

namespace granair {

std::unique_ptr<VoidFractionModel> LumpedVoidFraction::fromDictionary(const Dictionary&) {
    return std::make_unique<LumpedVoidFraction>();
}

void LumpedVoidFraction::stencil(const CellLocator&, const ParticleState&, int centreCell,
                                 std::vector<CellWeight>& out) const {
    out.assign(1, {centreCell, 1.0});
}

}  // namespace granair
