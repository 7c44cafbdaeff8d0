// LatzSchmidt.hpp: rheology "latzSchmidt", the kinetic + plastic closure of
// the GRAIN-type continuum model (Schmidt & Latz) calibrated for lactose.
//
// Equations, for solid volume fraction c [-] and granular temperature T [m2/s2]:
//     g_c    = 1 / (1 - c/c_max)                         (crowding, diverges at c_max)
//     p_k    = c T g_c                                   (kinetic pressure)
//     p_y    = H(c - c0) T0 (c - c0) g_c                 (yield pressure, zero below c0)
//     p      = p_k + p_y
//     f      = 1 + p_y/p_k = 1 + H(c - c0) T0 (c - c0) / (c T)
//     eta    = eta0    sqrt(T g_c) c f                   (shear viscosity)
//     lambda = lambda0 sqrt(T g_c) c f                   (conductivity of T)
//     eps_r  = eps0    sqrt(T g_c) f                     (dissipation rate)
//     tan(phi) = sqrt(eta0 eps0)                         (internal friction of the calibration)
// Units (checked term by term): T and T0 are [m2/s2], so p_k, p_y and p are
// [m2/s2], i.e. pressure per unit particle density (multiply by rho_p for
// Pa); eta0, lambda0 [m] times sqrt(T) [m/s] give eta, lambda in [m2/s]
// (kinematic; times rho_p gives Pa s); eps0 [1/m] times sqrt(T) gives eps_r
// in [1/s]; eta0 eps0 is dimensionless, as tan(phi) must be.
// Behaviour: below c0 the material is a granular gas (p, eta ~ sqrt(T));
// above c0 the plastic part f grows like 1/T as T -> 0, so eta ~ p_y/sqrt(T)
// diverges at rest (yield-stress behaviour) while p -> p_y stays finite;
// g_c keeps c below c_max (p -> infinity there).
//
// Limits and errors (InputError naming the value): c outside [0, c_max)
// (g_c is infinite at c_max and negative beyond); T <= 0 (the plastic factor
// divides by T; the model has no rest state, T is a transported field that
// stays positive); NaN or infinite inputs. At c = 0 the factor f is 1.
//
// Validity: dense and moderately dense flow of one powder, with the parameters
// calibrated on shear tests and silo discharge of that powder; not a
// predictive closure for other materials.
//
// Parameters (rheology dictionary; all required, the lactose values in brackets):
//   c0       [-]       onset of the plastic (yield) pressure       (0.5579)
//   cMax     [-]       maximum packing, c0 < cMax < 1               (0.5771)
//   T0       [m2/s2]   yield-pressure scale, >= 0                   (0.41)
//   eta0     [m]       viscosity length, > 0                        (0.00052)
//   lambda0  [m]       conductivity length, > 0                     (0.001)
//   eps0     [1/m]     dissipation inverse length, > 0              (332.84)
//
// Reference: the closures and the lactose parameters are those of the study
// "Modelling of granular flow on micro- and macroscopic scales with
// experimental and numerical calibration" (lactose powder discharge, GRAIN
// model), reference case A of this project. The original Schmidt & Latz model
// paper could not be located with the search tools available when this was
// written, so it is not cited here by volume and page.
#pragma once
#include <memory>
#include <string>

#include "rheology/Rheology.hpp"

namespace granair {

class LatzSchmidt final : public Rheology {
public:
    static constexpr const char* typeName = "latzSchmidt";

    struct Parameters {
        double c0 = 0, cMax = 0, T0 = 0, eta0 = 0, lambda0 = 0, eps0 = 0;
    };
    // The closure values at one (c, T), units as in the header comment.
    struct Values {
        double gc;      // [-]
        double pK;      // [m2/s2]
        double pY;      // [m2/s2]
        double p;       // [m2/s2]
        double eta;     // [m2/s]
        double lambda;  // [m2/s]
        double epsR;    // [1/s]
    };

    explicit LatzSchmidt(const Parameters& p);
    static std::unique_ptr<Rheology> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    std::vector<std::string> inputs() const override { return {"c", "T"}; }
    // p [m2/s2], eta [m2/s], lambda [m2/s], epsR [1/s].
    std::vector<RheologyQuantity> outputs() const override;
    std::vector<double> evaluate(const GranularState& s) const override;

    // All closure values at (c, T); throws InputError outside the limits above.
    Values values(double c, double T) const;
    double tanFrictionAngle() const;  // sqrt(eta0 eps0) [-]

    // The equation of state inverted for c: the solid fraction in [0, cMax)
    // at which p(c, T) = q, for q = p/rho_p [m2/s2] and T > 0 [m2/s2].
    // Multiplying p(c, T) = q by (1 - c/cMax) leaves an equation linear in c
    // on each side of c0, so the root is exact (no iteration):
    //     q <= q0 = c0 T g_c(c0):  c = q / (T + q/cMax)
    //     q >  q0:                 c = (q + T0 c0) / (T + T0 + q/cMax)
    // p is strictly increasing in c (c g_c and (c - c0) g_c both are), so the
    // root is unique. q <= 0 gives c = 0 (no tension: a powder at zero or
    // negative pressure is not packed). For very large q the second form
    // rounds to cMax; the result is then the largest double below cMax.
    // Throws InputError for a non-finite q or T <= 0.
    double solidFraction(double q, double T) const;

    // Homogeneous simple shear at fixed c: the temperature T* at which the
    // viscous heating eta gammaDot^2 balances the dissipation eps_r p_k,
    //     T* = eta0 gammaDot^2 / (eps0 g_c)      [m2/s2],
    // where the shear stress over the pressure is eta gammaDot / p = sqrt(eta0 eps0).
    // Requires 0 < c < cMax and gammaDot > 0.
    double steadyShearTemperature(double c, double gammaDot) const;

    const Parameters& parameters() const { return p_; }

private:
    Parameters p_;
};

}  // namespace granair
