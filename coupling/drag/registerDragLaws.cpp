// registerDragLaws.cpp: the registry of drag laws, built on first use from
// the list in drag/sources.cmake (generated into generated/drag/ModelList.hpp
// by cmake/GranairModels.cmake). A new law needs no edit here:
// docs/adding-a-model.md.
#include "drag/DragLaw.hpp"
#include "generated/drag/ModelList.hpp"

namespace granair {

const Registry<DragLaw>& dragLaws() {
    // Filled once, on first use (thread-safe since C++11).
    static const Registry<DragLaw> registry = makeRegistry<DragLaw>("drag law", DragLawList{});
    return registry;
}

}  // namespace granair
