// registerDragLaws.cpp: the registry of drag laws and the one function that
// fills it. A new law is added here, and needs a reference data file in
// tests/data/drag/<name>.dat (the unit tests fail without one).
#include "drag/BeetstraVanDerHoefKuipers.hpp"
#include "drag/DiFelice.hpp"
#include "drag/DragLaw.hpp"
#include "drag/ErgunGidaspow.hpp"
#include "drag/SchillerNaumann.hpp"
#include "drag/WenYu.hpp"

namespace granair {

namespace {

void registerDragLaws(Registry<DragLaw>& r) {
    r.add(ErgunGidaspow::typeName, ErgunGidaspow::fromDictionary);
    r.add(WenYu::typeName, WenYu::fromDictionary);
    r.add(DiFelice::typeName, DiFelice::fromDictionary);
    r.add(SchillerNaumann::typeName, SchillerNaumann::fromDictionary);
    r.add(BeetstraVanDerHoefKuipers::typeName, BeetstraVanDerHoefKuipers::fromDictionary);
}

}  // namespace

const Registry<DragLaw>& dragLaws() {
    // Filled once, on first use (thread-safe since C++11).
    static const Registry<DragLaw> registry = [] {
        Registry<DragLaw> r("drag law");
        registerDragLaws(r);
        return r;
    }();
    return registry;
}

}  // namespace granair
