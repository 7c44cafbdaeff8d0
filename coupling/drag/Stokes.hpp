// Stokes.hpp: drag law "Stokes", creeping flow past one sphere (THROW-AWAY
// model of the docs/adding-a-model.md check).
//
// Equation: F = 3 pi mu d (Uf - Up), so beta = 3 pi mu d [kg/s].
// Validity: Re << 1, single sphere. Parameters: none.
// Reference: Stokes, G.G. (1851). Trans. Cambridge Phil. Soc. 9, 8-106.
#pragma once
#include <memory>

#include "drag/DragLaw.hpp"

namespace granair {

class Stokes final : public DragLaw {
public:
    static constexpr const char* typeName = "Stokes";
    static std::unique_ptr<DragLaw> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    double beta(double d, double eps, double slip, const FluidProperties& f) const override;
};

}  // namespace granair
