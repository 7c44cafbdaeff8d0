// Rheology.hpp: the interface every continuum granular rheology implements.
//
// A rheology turns the local state of the granular phase into its transport
// coefficients. Two families exist, with different state variables:
//   - local (inertial-number) rheologies, e.g. muI: the viscosity follows from
//     the pressure p [Pa] and the shear rate gammaDot [1/s] alone
//     (ViscoplasticRheology below);
//   - kinetic + plastic closures, e.g. latzSchmidt: pressure, viscosity and the
//     granular-temperature transport coefficients follow from the solid volume
//     fraction c [-] and the granular temperature T [m2/s2], T being a
//     transported field of the full model.
// The common interface names its inputs and its outputs (with units), so one
// data-driven tester checks every model, and a solver can refuse a model it
// cannot feed with a message saying what is missing.
#pragma once
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"

namespace granair {

// The local state a rheology may read. Fields a model does not use stay NaN.
struct GranularState {
    static constexpr double unset = std::numeric_limits<double>::quiet_NaN();
    double p = unset;         // pressure [Pa] (muI: mixture pressure incl. the hydrostatic part)
    double gammaDot = unset;  // shear rate sqrt(2 D:D) [1/s], see ShearRate.hpp
    double c = unset;         // solid volume fraction [-]
    double T = unset;         // granular temperature [m2/s2]
};

// One output quantity of a rheology: its name in data files and its unit.
struct RheologyQuantity {
    std::string name;
    std::string unit;
};

class Rheology {
public:
    virtual ~Rheology() = default;
    virtual std::string name() const = 0;

    // Names of the GranularState fields the model reads ("p", "gammaDot", "c", "T").
    virtual std::vector<std::string> inputs() const = 0;
    // The quantities evaluate() returns, in order, with units.
    virtual std::vector<RheologyQuantity> outputs() const = 0;
    // Evaluate all outputs at state s; throws InputError naming a bad input value.
    virtual std::vector<double> evaluate(const GranularState& s) const = 0;
};

// A rheology whose viscosity depends on pressure and shear rate only, so an
// incompressible mixture solver (granairContinuumFoam) can use it cell by cell.
class ViscoplasticRheology : public Rheology {
public:
    // Granular dynamic viscosity [Pa s] at pressure p [Pa], shear rate gammaDot [1/s].
    virtual double viscosity(double p, double gammaDot) const = 0;
    // Solid volume fraction [-] of the flowing material at (p, gammaDot).
    virtual double solidFraction(double p, double gammaDot) const = 0;
    // The dimensionless flow state the model uses (the inertial number I) [-].
    virtual double inertialNumber(double p, double gammaDot) const = 0;
};

// The registry of rheologies (registerRheologies.cpp), filled on first use
// from the list in rheology/sources.cmake.
const Registry<Rheology>& rheologies();

}  // namespace granair
