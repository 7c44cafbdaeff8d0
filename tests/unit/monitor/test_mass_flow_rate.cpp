// MassFlowRate: a sliding-window rate recovers a constant discharge rate
// exactly, and a step change after one window.
#include <catch2/catch.hpp>

#include "core/Error.hpp"
#include "monitor/MassFlowRate.hpp"

TEST_CASE("windowed mass flow rate of a constant discharge is exact", "[monitor]") {
    granair::MassFlowRate w(0.1);
    const double rate = 0.0123;  // kg/s
    double last = 0;
    for (int k = 0; k <= 200; ++k) {
        const double t = 1e-3 * k;
        last = w.add(t, rate * t);
        if (k > 0) CHECK(last == Approx(rate).epsilon(1e-12));
    }
}

TEST_CASE("windowed rate follows a step change within one window", "[monitor]") {
    granair::MassFlowRate w(0.05);
    double m = 0, r = 0;
    for (int k = 1; k <= 300; ++k) {
        const double t = 1e-3 * k;
        m += (t <= 0.1 ? 0.01 : 0.03) * 1e-3;  // rate 0.01 then 0.03 kg/s
        r = w.add(t, m);
        if (t > 0.1 + 0.05 + 1e-3) CHECK(r == Approx(0.03).epsilon(1e-9));
    }
    CHECK(r == Approx(0.03).epsilon(1e-9));
}

TEST_CASE("mass flow window must be positive and time must increase", "[monitor]") {
    CHECK_THROWS_AS(granair::MassFlowRate(0.0), granair::InputError);
    granair::MassFlowRate w(0.1);
    w.add(1.0, 0.0);
    CHECK_THROWS(w.add(1.0, 0.0));
}
