// CentreVoidFraction.cpp: see CentreVoidFraction.hpp.
#include "voidfraction/CentreVoidFraction.hpp"

namespace granair {

std::unique_ptr<VoidFractionModel> CentreVoidFraction::fromDictionary(const Dictionary&) {
    return std::make_unique<CentreVoidFraction>();
}

void CentreVoidFraction::stencil(const CellLocator&, const ParticleState&, int centreCell,
                                 std::vector<CellWeight>& out) const {
    out.clear();
    out.push_back({centreCell, 1.0});
}

}  // namespace granair
