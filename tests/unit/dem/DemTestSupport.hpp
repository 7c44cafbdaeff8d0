// DemTestSupport.hpp: paths and closed forms shared by the DEM-side tests.
#pragma once
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace granair::dem::test {

// tests/data/dem/<name>
inline std::string script(const std::string& name) {
    return std::string(GRANAIR_TEST_DATA_DIR) + "/dem/" + name;
}

// Where a test's LIGGGHTS log and screen files go.
inline std::string logDir(const std::string& testName) {
    return std::string(GRANAIR_TEST_OUTPUT_DIR) + "/" + testName;
}

// The spheres of the test scripts: d = 2 mm, rho = 2500 kg/m3, so
// m = rho * 4/3 pi r^3 = 1.0471975511965977e-5 kg.
constexpr double sphereRadius = 1e-3;  // [m]
constexpr double sphereDensity = 2500;  // [kg/m3]
inline double sphereMass() {
    return sphereDensity * 4.0 / 3.0 * M_PI * sphereRadius * sphereRadius * sphereRadius;
}

constexpr double gravity = 9.81;  // [m/s2], `fix gravity 9.81 vector 0 0 -1`
constexpr double dt = 1e-5;  // [s], `timestep 1e-5`

// A sphere released from rest at height z0 [m] at time t0 [s], falling
// under gravity alone: z(t) = z0 - g (t - t0)^2 / 2.
struct Falling {
    double z0, t0;
    double z(double t) const { return z0 - 0.5 * gravity * (t - t0) * (t - t0); }
};

// The message of the granair::InputError that f() throws; "" if it throws
// nothing, "<other exception: ...>" if it throws anything else.
template <class F>
std::string inputErrorFrom(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("<other exception: ") + e.what() + ">";
    }
    return "";
}

}  // namespace granair::dem::test
