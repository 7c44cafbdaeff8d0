// registerCgKernels.cpp: the registry of CG kernel shapes.
//
// Every kernel is added here, explicitly, in one function (no static
// initialisers). To add a kernel: write its shape class (header with the
// equation, its exact line integral, parameters and reference), add one line
// below, list its .cpp in sources.cmake; tests/unit/cg checks the
// normalisation and the line integral of every registered kernel.
#include "cg/GaussKernel.hpp"
#include "cg/HeavisideKernel.hpp"
#include "cg/LucyKernel.hpp"

namespace granair {

namespace {
void registerCgKernels(Registry<CgKernelShape>& reg) {
    reg.add(GaussKernel::typeName, &GaussKernel::fromDict);
    reg.add(HeavisideKernel::typeName, &HeavisideKernel::fromDict);
    reg.add(LucyKernel::typeName, &LucyKernel::fromDict);
}
}  // namespace

const Registry<CgKernelShape>& cgKernelShapes() {
    static const Registry<CgKernelShape> registry = [] {
        Registry<CgKernelShape> reg("CG kernel");
        registerCgKernels(reg);
        return reg;
    }();
    return registry;
}

}  // namespace granair
