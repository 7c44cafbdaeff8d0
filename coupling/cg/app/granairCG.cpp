// granairCG: CG fields (continuum fields) from LIGGGHTS particle and contact dumps.
//
//   granairCG --particles 'dem/cg/particles_*.dump' --pairs 'dem/cg/pairs_*.dump'
//             --coordinates XZ --kernel gauss --width 1e-3 --n 100 200 --out results/cg
//   ./granair cg ...  (the same, with granair's environment)
//
// Options: granairCG --help; equations and conventions: docs/cg-fields.md.
// Plain C++ (coupling/cg): no OpenFOAM, no LIGGGHTS. Threads: OpenMP.
#include <iostream>
#include <string>
#include <vector>

#include "cg/CgOptions.hpp"
#include "cg/CgRun.hpp"
#include "core/Error.hpp"

int main(int argc, char** argv) {
    using namespace granair;
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        const CgOptions opt = CgOptions::fromArgs(args);
        if (opt.wantsHelp() || args.empty()) {
            std::cout << "granairCG: CG fields (density, velocity, stress, ...) from LIGGGHTS dumps.\n"
                         "usage: granairCG --particles GLOB [--pairs GLOB] [--walls GLOB] --width W [options]\n\n"
                      << CgOptions::help()
                      << "\nStress is positive in compression. Equations, conventions and the LIGGGHTS\n"
                         "dump snippet: docs/cg-fields.md.\n";
            return args.empty() ? 2 : 0;
        }
        runCg(CgRunSettings::fromOptions(opt), std::cout);
        return 0;
    } catch (const InputError& e) {
        std::cerr << "granairCG: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "granairCG: internal error: " << e.what() << "\n";
        return 3;
    }
}
