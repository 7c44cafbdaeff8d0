// MuI.hpp: rheology "muI", the local inertial-number (mu(I)) rheology of
// dense granular flow, tension-free, with a viscosity cap and floor and an
// optional partial regularisation of its ill-posedness.
//
// Equations (GDR MiDi 2004; Jop, Forterre & Pouliquen 2006):
//     I      = gammaDot d / sqrt(p / rho_p)                    inertial number [-]
//     mu(I)  = mu_s + (mu_2 - mu_s) / (I0/I + 1)               friction coefficient [-]
//     eta    = mu(I) p / gammaDot                              viscosity [Pa s]
//     phi(I) = phi_max - (phi_max - phi_min) I, clamped to [phi_min, phi_max]   (dilatancy)
// gammaDot = sqrt(2 D:D) (ShearRate.hpp), so the deviatoric stress
// tau = 2 eta D has magnitude |tau| = sqrt(tau:tau/2) = mu(I) p: a Coulomb
// yield criterion whose friction grows with I from mu_s (quasi-static) to
// mu_2 (I -> infinity).
//
// Limits (always on; they change the model only where it is singular):
//     p <= 0:      no tension. The powder carries no stress there: eta = etaMin,
//                  I = +infinity, phi = phi_min (Basilisk's granular.h does the
//                  same; Staron, Lagree & Popinet 2012). There is no pressure
//                  floor: a floor would give such cells a finite yield stress.
//     p > 0:       eta = clamp(mu(I) p / gammaDot_eff, etaMin, etaMax),
//                  gammaDot_eff = max(gammaDot, gammaDotMin) (no division by zero at rest)
//     etaMin       = rho_p d sqrt(g d) by default (Lagree, Staron & Popinet 2011,
//                  J. Fluid Mech. 686, 378, section 2.3.1): the viscosity of a
//                  grain-scale collisional flow, so a stress-free or fast-sheared
//                  cell is never inviscid (and the momentum equation never loses
//                  its viscous part inside the powder).
//     etaMax       the cap that turns rigid (unyielded) zones into a very viscous
//                  fluid creeping at ~ mu p / etaMax; raise it until the result no
//                  longer depends on it (cases/mcc-hopper README: the study).
// I, mu and phi are evaluated at (p, gammaDot_eff).
//
// Ill-posedness and the optional regularisation. Barker et al. (2015) showed
// that incompressible 2-D flow with this mu(I) is ill posed (short waves grow
// without bound, results do not converge under mesh refinement) wherever
//     C(I) = 4 nu^2 - 4 nu + mu^2 (1 - nu/2)^2 > 0,   nu = I mu'(I) / mu(I),
// which holds at low I and at high I. For the MCC parameters below the
// Jop form is ill posed for I < 1.841e-3 and I > 0.1059 (roots of C(I),
// see illPosedness(); checked in the unit tests). regularisation selects:
//   none           (default) the Jop form above.
//   barkerGray2017 the partial regularisation of Barker & Gray (2017):
//       I <  I1:  mu(I) = sqrt(alpha / ln(A/I))
//       I >= I1:  mu(I) = (mu_s I0 + mu_2 I + mu_inf I^2) / (I0 + I)
//     I1 is the lower root of C(I) = 0 for the Jop form (found by bisection
//     between 0 and I_zeta, where mu(I_zeta) = tan((atan mu_s + atan mu_2)/2)),
//     A = I1 exp(alpha (I0 + I1)^2 / (mu_s I0 + mu_2 I1 + mu_inf I1^2)^2)
//     makes mu continuous at I1. With alpha < 2 the low-I branch is well posed
//     for every I < I1 (there nu = 1/(2L), L = ln(A/I), and
//     C = (alpha - 2)/L + O(1/L^2) < 0 as I -> 0).
//     What it fixes: the low-I (creeping, quasi-static) ill-posedness.
//     What it does NOT fix: the high-I ill-posedness (for MCC with
//     mu_inf = 0.05 the model is still ill posed for I > 0.1099); it also
//     changes the physics at low I: mu(I) -> 0 (logarithmically) as I -> 0
//     instead of mu_s (MCC: mu(1e-6) = 0.322 instead of 0.401), so static
//     zones are weaker than the Coulomb limit; and mu -> mu_inf I instead of
//     mu_2 at high I. The limits above still apply.
//
// Validity: dense, dry, cohesionless grains of one size, I <~ 0.5 (beyond,
// collisional flow); incompressible form (phi(I) is an output used for the
// air drag, not fed back into the flow). No non-local effects (finite-size
// creep, hysteresis).
//
// Parameters (rheology dictionary):
//   muS          [-]       static friction mu_s, > 0                   (required)
//   mu2          [-]       limiting friction mu_2, > mu_s              (required)
//   I0           [-]       inertial-number scale, > 0                  (required)
//   d            [m]       particle diameter, > 0                      (required)
//   rhoP         [kg/m3]   particle (material) density, > 0            (required)
//   phiMax       [-]       solid fraction at I = 0, in (0, 1]          (default 0.632, MCC)
//   phiMin       [-]       solid fraction at I >= 1, in (0, phiMax]    (default 0.443, MCC)
//   etaMax       [Pa s]    viscosity cap, > etaMin                     (default 1e5)
//   etaMin       [Pa s]    viscosity floor, > 0               (default rho_p d sqrt(9.81 d))
//   (pMin        removed: a case that still sets it is refused with the reason)
//   gammaDotMin  [1/s]     shear-rate floor, > 0                       (default 1e-6)
//   regularisation         none | barkerGray2017                       (default none)
//   alphaReg     [-]       alpha of barkerGray2017, in (0, 2)          (default 1.9)
//   muInf        [-]       mu_inf of barkerGray2017, >= 0              (default 0.05)
// MCC spheres (VIVAPUR MCC Spheres 500, Remmelgas et al. 2019): muS 0.401,
// mu2 0.908, I0 0.0465, d 660e-6, rhoP 1500, phiMax 0.632, phiMin 0.443.
// The barkerGray2017 defaults are the values of the open OpenFOAM-muI
// implementation's tutorials (github.com/alexjarosch/OpenFOAM-muI), not
// fitted to MCC.
//
// References:
//     GDR MiDi (2004). On dense granular flows. Eur. Phys. J. E 14, 341-365.
//     Jop, P., Forterre, Y., Pouliquen, O. (2006). A constitutive law for dense
//     granular flows. Nature 441, 727-730.
//     Barker, T., Schaeffer, D.G., Bohorquez, P., Gray, J.M.N.T. (2015).
//     Well-posed and ill-posed behaviour of the mu(I)-rheology for granular
//     flow. J. Fluid Mech. 779, 794-818.
//     Barker, T., Gray, J.M.N.T. (2017). Partial regularisation of the
//     incompressible mu(I)-rheology for granular flow. J. Fluid Mech. 828, 5-32.
//     Remmelgas, J. et al. (2019). mu(I) rheology of MCC spheres, hopper
//     discharge with interFoam. Eur. J. Pharm. Sci. (case B of the reference cases).
#pragma once
#include <limits>
#include <memory>
#include <string>

#include "rheology/Rheology.hpp"

namespace granair {

class MuI final : public ViscoplasticRheology {
public:
    static constexpr const char* typeName = "muI";

    enum class Regularisation { none, barkerGray2017 };

    struct Parameters {
        double muS = 0, mu2 = 0, I0 = 0, d = 0, rhoP = 0;  // required
        double phiMax = 0.632, phiMin = 0.443;
        double etaMax = 1e5, gammaDotMin = 1e-6;
        double etaMin = std::numeric_limits<double>::quiet_NaN();  // NaN: rho_p d sqrt(g d)
        Regularisation regularisation = Regularisation::none;
        double alphaReg = 1.9, muInf = 0.05;
    };

    // Throws InputError on a parameter out of range (message names it).
    explicit MuI(const Parameters& p);
    // Reads the parameters above; errors name the file and key.
    static std::unique_ptr<Rheology> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    std::vector<std::string> inputs() const override { return {"p", "gammaDot"}; }
    // I [-], mu [-], eta [Pa s], phi [-], all at (p, gammaDot_eff); I = +inf where p <= 0.
    std::vector<RheologyQuantity> outputs() const override;
    std::vector<double> evaluate(const GranularState& s) const override;

    double viscosity(double p, double gammaDot) const override;
    double solidFraction(double p, double gammaDot) const override;

    // Inertial number at (p, max(gammaDot, gammaDotMin)); +infinity for p <= 0; inputs checked.
    double inertialNumber(double p, double gammaDot) const override;
    // mu(I) of the chosen form, I >= 0 (I = +infinity: its limit).
    double friction(double I) const;
    // d mu / d I of the chosen form, I > 0.
    double frictionDerivative(double I) const;
    // phi(I), clamped to [phiMin, phiMax] (phiMin for I = +infinity).
    double dilatancy(double I) const;
    // Barker et al. (2015) C(I) of the chosen form: > 0 ill posed, < 0 well posed.
    double illPosedness(double I) const;

    // The parameters, etaMin resolved to its value.
    const Parameters& parameters() const { return p_; }
    // Standard gravity of the default etaMin = rho_p d sqrt(g d) [m/s2].
    static constexpr double standardGravity = 9.81;
    // I1 and ln A of barkerGray2017 (NaN for none).
    double regularisationI1() const { return i1_; }
    double regularisationLogA() const { return logA_; }

private:
    Parameters p_;
    double i1_;
    double logA_;

    double jopFriction(double I) const;
    double jopFrictionDerivative(double I) const;
    void checkState(double p, double gammaDot) const;
};

}  // namespace granair
