// LatzSchmidt.cpp: see LatzSchmidt.hpp.
#include "rheology/LatzSchmidt.hpp"

#include <cmath>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace granair {

LatzSchmidt::LatzSchmidt(const Parameters& p) : p_(p) {
    auto check = [](bool good, const char* key, double v, const char* expected) {
        if (!good) failParameter(key, "rheology latzSchmidt: ", key, " = ", v, ", expected ", expected);
    };
    check(p_.c0 > 0 && p_.c0 < 1, "c0", p_.c0, "0 < c0 < 1");
    check(p_.cMax > p_.c0 && p_.cMax < 1, "cMax", p_.cMax, "c0 < cMax < 1");
    check(p_.T0 >= 0 && std::isfinite(p_.T0), "T0", p_.T0, "a finite T0 >= 0 [m2/s2]");
    check(p_.eta0 > 0 && std::isfinite(p_.eta0), "eta0", p_.eta0, "a finite eta0 > 0 [m]");
    check(p_.lambda0 > 0 && std::isfinite(p_.lambda0), "lambda0", p_.lambda0, "a finite lambda0 > 0 [m]");
    check(p_.eps0 > 0 && std::isfinite(p_.eps0), "eps0", p_.eps0, "a finite eps0 > 0 [1/m]");
}

std::unique_ptr<Rheology> LatzSchmidt::fromDictionary(const Dictionary& dict) {
    Parameters p;
    p.c0 = dict.getDouble("c0");
    p.cMax = dict.getDouble("cMax");
    p.T0 = dict.getDouble("T0");
    p.eta0 = dict.getDouble("eta0");
    p.lambda0 = dict.getDouble("lambda0");
    p.eps0 = dict.getDouble("eps0");
    return std::make_unique<LatzSchmidt>(p);  // the registry names the file of a bad value
}

std::vector<RheologyQuantity> LatzSchmidt::outputs() const {
    return {{"p", "m2/s2"}, {"eta", "m2/s"}, {"lambda", "m2/s"}, {"epsR", "1/s"}};
}

LatzSchmidt::Values LatzSchmidt::values(double c, double T) const {
    if (!(c >= 0 && c < p_.cMax))
        fail<InputError>("rheology latzSchmidt: solid volume fraction c = ", c, " outside [0, cMax = ", p_.cMax,
                         "); g_c = 1/(1 - c/cMax) is infinite at cMax");
    if (!(T > 0 && std::isfinite(T)))
        fail<InputError>("rheology latzSchmidt: granular temperature T = ", T,
                         " m2/s2, expected a finite T > 0 (the plastic factor divides by T)");
    Values v;
    v.gc = 1.0 / (1.0 - c / p_.cMax);
    v.pK = c * T * v.gc;
    const bool plastic = c > p_.c0;
    v.pY = plastic ? p_.T0 * (c - p_.c0) * v.gc : 0.0;
    v.p = v.pK + v.pY;
    // 1 + p_y/p_k with g_c cancelled, so c = 0 (p_k = 0, p_y = 0) gives 1.
    const double f = plastic ? 1.0 + p_.T0 * (c - p_.c0) / (c * T) : 1.0;
    const double s = std::sqrt(T * v.gc);
    v.eta = p_.eta0 * s * c * f;
    v.lambda = p_.lambda0 * s * c * f;
    v.epsR = p_.eps0 * s * f;
    return v;
}

std::vector<double> LatzSchmidt::evaluate(const GranularState& s) const {
    const Values v = values(s.c, s.T);
    return {v.p, v.eta, v.lambda, v.epsR};
}

double LatzSchmidt::tanFrictionAngle() const { return std::sqrt(p_.eta0 * p_.eps0); }

double LatzSchmidt::solidFraction(double q, double T) const {
    if (!std::isfinite(q))
        fail<InputError>("rheology latzSchmidt: pressure per particle density q = ", q,
                         " m2/s2, expected a finite number");
    if (!(T > 0 && std::isfinite(T)))
        fail<InputError>("rheology latzSchmidt: granular temperature T = ", T,
                         " m2/s2, expected a finite T > 0 to invert the equation of state");
    if (q <= 0) return 0.0;
    const double gc0 = 1.0 / (1.0 - p_.c0 / p_.cMax);
    const double q0 = p_.c0 * T * gc0;  // pressure at c = c0 (p_y = 0 there)
    double c = q <= q0 ? q / (T + q / p_.cMax) : (q + p_.T0 * p_.c0) / (T + p_.T0 + q / p_.cMax);
    // Both forms are < cMax in exact arithmetic; keep that after rounding.
    if (!(c < p_.cMax)) c = std::nextafter(p_.cMax, 0.0);
    return c;
}

double LatzSchmidt::steadyShearTemperature(double c, double gammaDot) const {
    if (!(c > 0 && c < p_.cMax))
        fail<InputError>("rheology latzSchmidt: steady shear needs 0 < c < cMax = ", p_.cMax, ", got c = ", c);
    if (!(gammaDot > 0 && std::isfinite(gammaDot)))
        fail<InputError>("rheology latzSchmidt: steady shear needs a finite shear rate > 0, got ", gammaDot, " 1/s");
    const double gc = 1.0 / (1.0 - c / p_.cMax);
    return p_.eta0 * gammaDot * gammaDot / (p_.eps0 * gc);
}

}  // namespace granair
