// parcelBeta.cpp: drag coefficient of a coarse-grained parcel (see DragLaw.hpp).
//
// Radl et al. (2011): a parcel of coarse-graining factor s stands for s^3
// primary particles of diameter dParcel/s, each feeling the drag of a primary
// particle at the local void fraction and slip, so beta_parcel = s^3 beta(d/s).
// Re and Cd are therefore evaluated with the primary diameter.
//
// Reference:
//     Radl, S., Radeke, C., Khinast, J.G., Sundaresan, S. (2011). Parcel-based
//     approach for the simulation of gas-particle flows. Proc. 8th Int. Conf.
//     on CFD in Oil & Gas, Metallurgical and Process Industries, Trondheim.
#include <cmath>

#include "core/Error.hpp"
#include "drag/DragLaw.hpp"

namespace granair {

double parcelBeta(const DragLaw& law, double dParcel, double s, double eps, double slip,
                  const FluidProperties& f) {
    if (!(std::isfinite(s) && s >= 1))
        fail<InputError>("drag law ", law.name(), ": coarse-graining factor ", s,
                         ", expected a finite s >= 1");
    return s * s * s * law.beta(dParcel / s, eps, slip, f);
}

}  // namespace granair
