// registerRheologies.cpp: the registry of continuum rheologies and the one
// function that fills it. A new rheology is added here, and needs a reference
// data file tests/data/rheology/<name>.dat (the unit tests fail without one).
#include "rheology/LatzSchmidt.hpp"
#include "rheology/MuI.hpp"
#include "rheology/Rheology.hpp"

namespace granair {

namespace {

void registerRheologies(Registry<Rheology>& r) {
    r.add(MuI::typeName, MuI::fromDictionary);
    r.add(LatzSchmidt::typeName, LatzSchmidt::fromDictionary);
}

}  // namespace

const Registry<Rheology>& rheologies() {
    // Filled once, on first use (thread-safe since C++11).
    static const Registry<Rheology> registry = [] {
        Registry<Rheology> r("rheology");
        registerRheologies(r);
        return r;
    }();
    return registry;
}

}  // namespace granair
