// CentreVoidFraction.hpp: the particle-centroid void-fraction model ("centre").
//
// Summary: a particle's whole volume goes to the cell that holds its centre.
//
// Stencil: { (centreCell, 1) }.  So the solid volume of cell c is
//     Vs_c = sum over particles p with centre in c of V_p,   V_p = 4/3 pi r_p^3,
// and the coupling step forms eps_c = 1 - Vs_c / V_c.
//
// Validity: cells several particle diameters wide (CFDEM's guidance is a cell
// at least ~3 particle diameters). With smaller cells Vs_c can exceed V_c (the
// coupling step floors eps) and eps jumps each time a particle crosses a face.
// It is the only model whose result is exactly independent of the
// decomposition: it never needs a neighbouring cell, local or not.
//
// Parameters: none.
//
// Reference: CFDEMcoupling documentation, voidFractionModel_centreVoidFraction
// (https://www.cfdem.com/media/CFDEM/docu/voidFractionModel_centreVoidFraction.html);
// Goniva, C., Kloss, C., Deen, N.G., Kuipers, J.A.M., Pirker, S. (2012),
// Influence of rolling friction on single spout fluidized bed simulation,
// Particuology 10(5):582-591.
#pragma once
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

class CentreVoidFraction : public VoidFractionModel {
public:
    static constexpr const char* typeName = "centre";
    // No parameters.
    static std::unique_ptr<VoidFractionModel> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    void stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                 std::vector<CellWeight>& out) const override;
    bool centreCellOnly() const override { return true; }
};

}  // namespace granair
