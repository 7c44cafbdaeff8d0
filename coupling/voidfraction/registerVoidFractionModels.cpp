// registerVoidFractionModels.cpp: the registry of void-fraction models, built
// on first use from the list in voidfraction/sources.cmake (generated into
// generated/voidfraction/ModelList.hpp by cmake/GranairModels.cmake). A new
// model needs no edit here: docs/adding-a-model.md.
#include "generated/voidfraction/ModelList.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

const Registry<VoidFractionModel>& voidFractionModels() {
    // Filled once, on first use (thread-safe since C++11).
    static const Registry<VoidFractionModel> registry =
        makeRegistry<VoidFractionModel>("void-fraction model", VoidFractionModelList{});
    return registry;
}

}  // namespace granair
