// DragInputCheck.cpp: see DragInputCheck.hpp.
#include "drag/DragInputCheck.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace granair {

void checkDragInput(const char* lawName, double d, double eps, double slip, const FluidProperties& f) {
    const auto who = [lawName] { return std::string("drag law ") + lawName + ": "; };
    // Written as !(good) so that NaN, which fails every comparison, is caught too.
    if (!(std::isfinite(d) && d > 0)) fail<InputError>(who(), "particle diameter ", d, " m, expected a finite d > 0");
    if (!(eps > 0 && eps <= 1)) fail<InputError>(who(), "void fraction ", eps, " outside (0, 1]");
    if (!(std::isfinite(slip) && slip >= 0))
        fail<InputError>(who(), "slip velocity ", slip, " m/s, expected a finite |Uf - Up| >= 0");
    if (!(std::isfinite(f.rho) && f.rho > 0))
        fail<InputError>(who(), "fluid density ", f.rho, " kg/m3, expected a finite rho > 0");
    if (!(std::isfinite(f.mu) && f.mu > 0))
        fail<InputError>(who(), "fluid viscosity ", f.mu, " Pa s, expected a finite mu > 0");
}

}  // namespace granair
