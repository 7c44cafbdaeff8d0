// MassFlowRate.cpp: see MassFlowRate.hpp.
#include "monitor/MassFlowRate.hpp"

#include "core/Error.hpp"

namespace granair {

MassFlowRate::MassFlowRate(double window) : window_(window) {
    if (!(window > 0)) fail<InputError>("mass flow window must be > 0 s, got ", window);
}

double MassFlowRate::add(double t, double m) {
    if (!history_.empty() && t <= history_.back().first)
        fail("MassFlowRate: times must increase (", t, " after ", history_.back().first, ")");
    history_.emplace_back(t, m);
    // Keep the newest sample at or before t - window as the window's start.
    while (history_.size() > 2 && history_[1].first <= t - window_) history_.pop_front();
    const auto& first = history_.front();
    const double dt = t - first.first;
    return dt > 0 ? (m - first.second) / dt : 0.0;
}

}  // namespace granair

namespace granair {

void MassFlowRate::restore(History history) {
    for (std::size_t k = 1; k < history.size(); ++k)
        if (!(history[k].first > history[k - 1].first))
            fail<InputError>("mass flow window: restart samples must have increasing times (", history[k].first,
                             " after ", history[k - 1].first, ")");
    history_ = std::move(history);
}

}  // namespace granair
