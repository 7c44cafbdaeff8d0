// CgTimeAverage.hpp: weights of the snapshots in a time average of CG fields.
//
// The raw fields are additive, so a time average is sum_k w_k F_k with
// sum_k w_k = 1; velocity, kinetic stress and the rest are then derived from
// the averaged raw fields (so the kinetic stress includes the velocity
// fluctuations in time about the time-averaged velocity, as for a steady
// flow's stress).
//   uniform: w_k = 1/N over the snapshots with t0 <= t_k <= t1;
//   gauss:   w_k ~ exp(-(t_k - tc)^2 / (2 s^2)) for |t_k - tc| <= 3 s,
//            normalised over the snapshots present (MercuryCG's
//            TimeSmoothedCG uses a Gaussian in time the same way).
#pragma once
#include <string>
#include <vector>

namespace granair {

struct CgTimeAverage {
    enum class Kind { uniform, gauss } kind = Kind::uniform;
    double from = -1e300, to = 1e300;  // uniform window [s]
    double centre = 0.0, width = 0.0;  // gauss centre and standard deviation [s]

    // "uniform" or "gauss"; anything else throws InputError naming `where`.
    static Kind parseKind(const std::string& name, const std::string& where);
    // One weight per time; throws InputError when no snapshot gets a weight.
    std::vector<double> weights(const std::vector<double>& times) const;
    std::string describe() const;
};

}  // namespace granair
