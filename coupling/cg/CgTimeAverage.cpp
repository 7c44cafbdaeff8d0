// CgTimeAverage.cpp: see CgTimeAverage.hpp.
#include "cg/CgTimeAverage.hpp"

#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace granair {

CgTimeAverage::Kind CgTimeAverage::parseKind(const std::string& name, const std::string& where) {
    if (name == "uniform") return Kind::uniform;
    if (name == "gauss") return Kind::gauss;
    fail<InputError>(where, ": unknown time average '", name, "'. Known time averages: gauss uniform");
}

std::vector<double> CgTimeAverage::weights(const std::vector<double>& times) const {
    std::vector<double> w(times.size(), 0.0);
    double sum = 0.0;
    if (kind == Kind::gauss && !(width > 0.0))
        fail<InputError>("gauss time average: width ", width, " s, expected > 0");
    for (std::size_t k = 0; k < times.size(); ++k) {
        const double t = times[k];
        if (kind == Kind::uniform) {
            if (t >= from && t <= to) w[k] = 1.0;
        } else {
            const double u = (t - centre) / width;
            if (std::abs(u) <= 3.0) w[k] = std::exp(-0.5 * u * u);
        }
        sum += w[k];
    }
    if (!(sum > 0.0)) {
        std::ostringstream os;
        os << "time average (" << describe() << "): no snapshot inside it; snapshot times";
        if (times.empty()) os << " (none)";
        else os << " " << times.front() << " to " << times.back() << " s";
        fail<InputError>(os.str());
    }
    for (auto& x : w) x /= sum;
    return w;
}

std::string CgTimeAverage::describe() const {
    std::ostringstream os;
    os.precision(8);
    if (kind == Kind::uniform) {
        os << "uniform";
        if (from > -1e300 || to < 1e300) os << " over " << from << " to " << to << " s";
    } else {
        os << "gauss about t = " << centre << " s, width " << width << " s (cut at 3 widths)";
    }
    return os.str();
}

}  // namespace granair
