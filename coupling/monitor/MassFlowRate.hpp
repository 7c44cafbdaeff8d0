// MassFlowRate.hpp: discharge rate from the cumulative discharged mass.
//
// W(t) = (M(t) - M(t - T)) / T over a sliding window of length T: a raw
// per-step difference is far too noisy (particles leave one by one), and a
// window of the order of 0.05-0.2 s is what experiments with a balance give.
// Until a full window has passed, the window is the time elapsed so far.
#pragma once
#include <deque>
#include <utility>

namespace granair {

class MassFlowRate {
public:
    explicit MassFlowRate(double window);
    // Record the cumulative discharged mass M [kg] at time t [s] (t increasing)
    // and return the windowed rate [kg/s].
    double add(double t, double cumulativeMass);
    double window() const { return window_; }
    // The samples (t, M) the window still needs, for a restart point.
    using History = std::deque<std::pair<double, double>>;
    const History& history() const { return history_; }
    // Continue from a restart point's samples (times increasing).
    void restore(History history);

private:
    double window_;
    History history_;
};

}  // namespace granair
