// FormatExact.cpp: see FormatExact.hpp.
#include "output/FormatExact.hpp"

#include <cstdio>
#include <cstdlib>

namespace granair {

std::string formatExact(double v) {
    char buf[32];
    for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace granair
