// Newtonian.cpp: see Newtonian.hpp.
#include "rheology/Newtonian.hpp"

#include <cmath>

namespace granair {

Newtonian::Newtonian(double eta0, double phi0) : eta0_(eta0), phi0_(phi0) {
    if (!(eta0 > 0 && std::isfinite(eta0)))
        failParameter("eta0", "rheology newtonian: eta0 = ", eta0, ", expected a finite eta0 > 0 [Pa s]");
    if (!(phi0 > 0 && phi0 <= 1)) failParameter("phi0", "rheology newtonian: phi0 = ", phi0, ", expected 0 < phi0 <= 1");
}

std::unique_ptr<Rheology> Newtonian::fromDictionary(const Dictionary& dict) {
    return std::make_unique<Newtonian>(dict.getDouble("eta0"), dict.getDouble("phi0", 0.6));
}

std::vector<double> Newtonian::evaluate(const GranularState&) const { return {eta0_, phi0_}; }

}  // namespace granair
