// Vec3.hpp: the 3-vector used across the coupling layer (Eigen, fixed size).
#pragma once
#include <Eigen/Core>

namespace granair {

using Vec3 = Eigen::Vector3d;

// Axis-aligned box; used for subdomain bounds in the exchange.
struct Box {
    Vec3 lo{Vec3::Constant(1e300)};
    Vec3 hi{Vec3::Constant(-1e300)};

    bool contains(const Vec3& x) const {
        return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
    }
    bool empty() const { return (hi.array() < lo.array()).any(); }
    void expand(const Vec3& x) {
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
    }
    Box inflated(double by) const {
        return Box{lo - Vec3::Constant(by), hi + Vec3::Constant(by)};
    }
};

}  // namespace granair
