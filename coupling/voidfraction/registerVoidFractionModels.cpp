// registerVoidFractionModels.cpp: the registry of void-fraction models.
//
// Every model is added here, explicitly, in one function (no static
// initialisers). To add a model: write its class (header with summary,
// equation, validity, parameters and reference), add one line below, list its
// .cpp in sources.cmake, and add tests/data/voidfraction/<type>.dict (the
// shared tests fail for a registered model without one).
#include "voidfraction/CentreVoidFraction.hpp"
#include "voidfraction/DividedVoidFraction.hpp"
#include "voidfraction/GaussianVoidFraction.hpp"

namespace granair {

namespace {
void registerVoidFractionModels(Registry<VoidFractionModel>& reg) {
    reg.add(CentreVoidFraction::typeName,
            [](const Dictionary&) { return std::make_unique<CentreVoidFraction>(); });
    reg.add(DividedVoidFraction::typeName, &DividedVoidFraction::fromDict);
    reg.add(GaussianVoidFraction::typeName, &GaussianVoidFraction::fromDict);
}
}  // namespace

const Registry<VoidFractionModel>& voidFractionModels() {
    static const Registry<VoidFractionModel> registry = [] {
        Registry<VoidFractionModel> reg("void-fraction model");
        registerVoidFractionModels(reg);
        return reg;
    }();
    return registry;
}

}  // namespace granair
