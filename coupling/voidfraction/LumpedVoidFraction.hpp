// LumpedVoidFraction.hpp: void-fraction model "lumped" (THROW-AWAY model of
// the docs/adding-a-model.md check): the whole particle volume in its centre
// cell. Stencil { (centreCell, 1) }. Parameters: none.
#pragma once
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

class LumpedVoidFraction : public VoidFractionModel {
public:
    static constexpr const char* typeName = "lumped";
    static std::unique_ptr<VoidFractionModel> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    void stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                 std::vector<CellWeight>& out) const override;
};

}  // namespace granair
