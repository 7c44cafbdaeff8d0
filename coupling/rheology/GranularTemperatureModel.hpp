// GranularTemperatureModel.hpp: the latzSchmidt closure as an incompressible
// mixture solver (granairContinuumFoam) uses it, cell by cell: the solid
// fraction from the mechanical pressure, the viscosity and conductivity in
// solver units with a cap, and the source terms of the granular-temperature
// equation. docs/continuum-model.md derives the formulation.
//
// Granular-temperature equation (per unit particle density, T [m2/s2]):
//     (3/2) c (dT/dt + U.grad T) = 2 nu D:D + div(lambda grad T) - eps_r p_k
// with nu = eta of LatzSchmidt.hpp [m2/s] (the pressure-work term -p div U
// vanishes in the incompressible mixture). With gammaDot = sqrt(2 D:D),
//     production  P = nu gammaDot^2                [m2/s3]
//     dissipation S = eps_r p_k                    [m2/s3]
// For c > 0 both follow from the pressure and s = sqrt(T g_c) alone:
// nu = eta0 p/s and S = eps0 p s (p = p_k + p_y = p_k (1 + p_y/p_k)), so S/T
// (sinkRate) is the coefficient of an implicit, positivity-keeping sink.
//
// Per cell, from the mixture pressure p [Pa], T [m2/s2], gammaDot [1/s]:
//     q   = p / rhoP                         pressure per particle density [m2/s2]
//     c   = solid fraction at which the equation of state gives q
//           (LatzSchmidt::solidFraction; 0 where q <= 0)
//     k   = min(1, nuMax / nu),  nuMax = etaMax / rhoP
//     eta = rhoP k nu  [Pa s],  lambda = k lambda_LS [m2/s],  P = k nu gammaDot^2
// The cap scales viscosity and conductivity by the same factor k (their ratio
// lambda0/eta0 is the model's), and the heating uses the capped viscosity, so
// it is the work the momentum equation's stress actually does. The
// dissipation is not capped. T must be > 0: the solver floors it at TMin.
//
// Parameters (the rheology dictionary, beside the LatzSchmidt ones):
//   rhoP    [kg/m3]  particle (material) density, > 0     (required; lactose 1060)
//   etaMax  [Pa s]   viscosity cap, > 0                   (default 1e5, as muI)
//   TMin    [m2/s2]  floor of T, > 0                      (default 1e-12: fluctuation
//                    velocity 1 um/s; at p >~ 10 Pa the cap (1e3 Pa s), not TMin, then sets eta)
#pragma once
#include "rheology/LatzSchmidt.hpp"

namespace granair {

class GranularTemperatureModel {
public:
    struct Parameters {
        double rhoP = 0;
        double etaMax = 1e5;
        double TMin = 1e-12;
    };
    // What the solver needs in one cell.
    struct Cell {
        double c;            // solid fraction [-]
        double eta;          // capped viscosity [Pa s]
        double lambda;       // capped conductivity of T [m2/s]
        double production;   // P = k nu gammaDot^2 [m2/s3]
        double dissipation;  // S = eps_r p_k [m2/s3]
        double sinkRate;     // S / T [1/s]
        bool capped;         // the cap was active
    };

    // Throws ParameterError (an InputError, core/Registry.hpp) naming a parameter out of range.
    GranularTemperatureModel(const LatzSchmidt& closure, const Parameters& p);
    // The closure from the rheology registry (type latzSchmidt and its keys),
    // plus rhoP, etaMax, TMin; errors name the file and key.
    static GranularTemperatureModel fromDictionary(const Dictionary& dict);

    // Throws InputError (naming the value) for non-finite p, T <= 0, gammaDot < 0.
    Cell evaluate(double p, double T, double gammaDot) const;

    const LatzSchmidt& closure() const { return closure_; }
    const Parameters& parameters() const { return p_; }

private:
    LatzSchmidt closure_;
    Parameters p_;
};

}  // namespace granair
