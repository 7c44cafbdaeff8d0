// registerRheologies.cpp: the registry of continuum rheologies, built on
// first use from the list in rheology/sources.cmake (generated into
// generated/rheology/ModelList.hpp by cmake/GranairModels.cmake). A new
// rheology needs no edit here: docs/adding-a-model.md.
#include "generated/rheology/ModelList.hpp"
#include "rheology/Rheology.hpp"

namespace granair {

const Registry<Rheology>& rheologies() {
    // Filled once, on first use (thread-safe since C++11).
    static const Registry<Rheology> registry = makeRegistry<Rheology>("rheology", RheologyList{});
    return registry;
}

}  // namespace granair
