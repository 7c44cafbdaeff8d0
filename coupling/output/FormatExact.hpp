// FormatExact.hpp: the shortest decimal text of a double that reads back to
// the same double, for the writers of time values (TimeSeriesWriter's CSV,
// ParticleVtkWriter's .pvd): exact, yet 0.1 stays "0.1" (%.17g alone would
// print 0.10000000000000001).
#pragma once
#include <string>

namespace granair {

// Shortest of %.15g .. %.17g that reads back to v.
std::string formatExact(double v);

}  // namespace granair
