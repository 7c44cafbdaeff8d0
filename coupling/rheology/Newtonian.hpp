// Newtonian.hpp: rheology "newtonian", a constant viscosity (THROW-AWAY model
// of the docs/adding-a-model.md check).
//
// Equation: eta = eta0, phi = phi0, I = 0, whatever p and gammaDot.
// Parameters: eta0 [Pa s] > 0 (required), phi0 [-] in (0, 1] (default 0.6).
#pragma once
#include <memory>

#include "rheology/Rheology.hpp"

namespace granair {

class Newtonian final : public ViscoplasticRheology {
public:
    static constexpr const char* typeName = "newtonian";

    Newtonian(double eta0, double phi0);
    static std::unique_ptr<Rheology> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    std::vector<std::string> inputs() const override { return {"p", "gammaDot"}; }
    std::vector<RheologyQuantity> outputs() const override { return {{"eta", "Pa s"}, {"phi", "-"}}; }
    std::vector<double> evaluate(const GranularState& s) const override;

    double viscosity(double, double) const override { return eta0_; }
    double solidFraction(double, double) const override { return phi0_; }
    double inertialNumber(double, double) const override { return 0.0; }

private:
    double eta0_, phi0_;
};

}  // namespace granair
