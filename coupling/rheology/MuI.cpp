// MuI.cpp: see MuI.hpp.
#include "rheology/MuI.hpp"

#include <algorithm>
#include <cmath>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace granair {

namespace {

// C(I) of Barker et al. (2015) from mu and I mu'/mu.
double barkerC(double mu, double nu) {
    const double b = 1.0 - 0.5 * nu;
    return 4.0 * nu * nu - 4.0 * nu + mu * mu * b * b;
}

}  // namespace

MuI::MuI(const Parameters& p) : p_(p), i1_(NAN), logA_(NAN) {
    auto check = [](bool good, const char* key, double v, const char* expected) {
        if (!good) failParameter(key, "rheology muI: ", key, " = ", v, ", expected ", expected);
    };
    // Written as good-conditions so that NaN fails every one of them.
    check(p_.muS > 0 && std::isfinite(p_.muS), "muS", p_.muS, "a finite mu_s > 0");
    check(p_.mu2 > p_.muS && std::isfinite(p_.mu2), "mu2", p_.mu2, "a finite mu_2 > mu_s");
    check(p_.I0 > 0 && std::isfinite(p_.I0), "I0", p_.I0, "a finite I0 > 0");
    check(p_.d > 0 && std::isfinite(p_.d), "d", p_.d, "a finite particle diameter > 0 [m]");
    check(p_.rhoP > 0 && std::isfinite(p_.rhoP), "rhoP", p_.rhoP, "a finite particle density > 0 [kg/m3]");
    check(p_.phiMax > 0 && p_.phiMax <= 1, "phiMax", p_.phiMax, "0 < phiMax <= 1");
    check(p_.phiMin > 0 && p_.phiMin <= p_.phiMax, "phiMin", p_.phiMin, "0 < phiMin <= phiMax");
    check(p_.etaMax > 0 && std::isfinite(p_.etaMax), "etaMax", p_.etaMax, "a finite viscosity cap > 0 [Pa s]");
    check(p_.pMin > 0 && std::isfinite(p_.pMin), "pMin", p_.pMin, "a finite pressure floor > 0 [Pa]");
    check(p_.gammaDotMin > 0 && std::isfinite(p_.gammaDotMin), "gammaDotMin", p_.gammaDotMin,
          "a finite shear-rate floor > 0 [1/s]");
    if (p_.regularisation != Regularisation::barkerGray2017) return;

    check(p_.alphaReg > 0 && p_.alphaReg < 2, "alphaReg", p_.alphaReg,
          "0 < alphaReg < 2 (alpha >= 2 leaves the low-I branch ill posed)");
    check(p_.muInf >= 0 && std::isfinite(p_.muInf), "muInf", p_.muInf, "a finite mu_inf >= 0");
    // I1: lower root of C(I) = 0 for the Jop form. C(0) = mu_s^2 > 0; at
    // I_zeta (friction angle halfway between the two limits) the Jop form is
    // well posed for any usual parameters, C < 0; bisect in between.
    const double tanZeta = std::tan(0.5 * (std::atan(p_.muS) + std::atan(p_.mu2)));
    const double iZeta = p_.I0 * (tanZeta - p_.muS) / (p_.mu2 - tanZeta);
    auto cJop = [this](double I) {
        const double mu = jopFriction(I);
        return barkerC(mu, I * jopFrictionDerivative(I) / mu);
    };
    if (!(cJop(iZeta) < 0))
        failParameter("regularisation",
                      "rheology muI: regularisation barkerGray2017 needs a well-posed range of the mu(I) law, but ",
                      "C(I) = ", cJop(iZeta), " >= 0 at I = ", iZeta, " (muS ", p_.muS, ", mu2 ", p_.mu2, ", I0 ",
                      p_.I0, ")");
    double lo = 0.0, hi = iZeta;
    for (;;) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;  // interval at machine resolution
        (cJop(mid) < 0 ? hi : lo) = mid;
    }
    i1_ = hi;
    const double q = (p_.I0 + i1_) / (p_.muS * p_.I0 + p_.mu2 * i1_ + p_.muInf * i1_ * i1_);
    logA_ = std::log(i1_) + p_.alphaReg * q * q;
}

std::unique_ptr<Rheology> MuI::fromDictionary(const Dictionary& dict) {
    Parameters p;
    p.muS = dict.getDouble("muS");
    p.mu2 = dict.getDouble("mu2");
    p.I0 = dict.getDouble("I0");
    p.d = dict.getDouble("d");
    p.rhoP = dict.getDouble("rhoP");
    p.phiMax = dict.getDouble("phiMax", p.phiMax);
    p.phiMin = dict.getDouble("phiMin", p.phiMin);
    p.etaMax = dict.getDouble("etaMax", p.etaMax);
    p.pMin = dict.getDouble("pMin", p.pMin);
    p.gammaDotMin = dict.getDouble("gammaDotMin", p.gammaDotMin);
    const std::string reg = dict.getString("regularisation", "none");
    if (reg == "barkerGray2017")
        p.regularisation = Regularisation::barkerGray2017;
    else if (reg != "none")
        fail<InputError>(dict.where("regularisation"), ": unknown regularisation '", reg,
                         "', expected one of: none barkerGray2017");
    p.alphaReg = dict.getDouble("alphaReg", p.alphaReg);
    p.muInf = dict.getDouble("muInf", p.muInf);
    return std::make_unique<MuI>(p);  // the registry names the file of a bad value
}

std::vector<RheologyQuantity> MuI::outputs() const {
    return {{"I", "-"}, {"mu", "-"}, {"eta", "Pa s"}, {"phi", "-"}};
}

void MuI::checkState(double p, double gammaDot) const {
    if (!std::isfinite(p))
        fail<InputError>("rheology muI: pressure ", p, " Pa, expected a finite number (values below pMin = ", p_.pMin,
                         " Pa are floored)");
    if (!(std::isfinite(gammaDot) && gammaDot >= 0))
        fail<InputError>("rheology muI: shear rate ", gammaDot, " 1/s, expected a finite gammaDot >= 0");
}

double MuI::inertialNumber(double p, double gammaDot) const {
    checkState(p, gammaDot);
    const double pEff = std::max(p, p_.pMin);
    const double gEff = std::max(gammaDot, p_.gammaDotMin);
    return gEff * p_.d * std::sqrt(p_.rhoP / pEff);
}

double MuI::jopFriction(double I) const { return p_.muS + (p_.mu2 - p_.muS) * I / (p_.I0 + I); }

double MuI::jopFrictionDerivative(double I) const {
    const double s = p_.I0 + I;
    return (p_.mu2 - p_.muS) * p_.I0 / (s * s);
}

double MuI::friction(double I) const {
    if (!(I >= 0)) fail<InputError>("rheology muI: inertial number ", I, ", expected I >= 0");
    if (p_.regularisation == Regularisation::none) return jopFriction(I);
    if (I < i1_) return I > 0 ? std::sqrt(p_.alphaReg / (logA_ - std::log(I))) : 0.0;
    return (p_.muS * p_.I0 + p_.mu2 * I + p_.muInf * I * I) / (p_.I0 + I);
}

double MuI::frictionDerivative(double I) const {
    if (!(I > 0)) fail<InputError>("rheology muI: inertial number ", I, ", expected I > 0 for d mu/dI");
    if (p_.regularisation == Regularisation::none) return jopFrictionDerivative(I);
    if (I < i1_) {
        const double L = logA_ - std::log(I);
        return std::sqrt(p_.alphaReg) / (2.0 * I * L * std::sqrt(L));
    }
    const double s = p_.I0 + I;
    const double n = p_.muS * p_.I0 + p_.mu2 * I + p_.muInf * I * I;
    return ((p_.mu2 + 2.0 * p_.muInf * I) * s - n) / (s * s);
}

double MuI::illPosedness(double I) const {
    const double mu = friction(I);
    return barkerC(mu, I * frictionDerivative(I) / mu);
}

double MuI::dilatancy(double I) const {
    const double phi = p_.phiMax - (p_.phiMax - p_.phiMin) * I;
    return std::clamp(phi, p_.phiMin, p_.phiMax);
}

double MuI::viscosity(double p, double gammaDot) const {
    const double I = inertialNumber(p, gammaDot);  // checks the inputs
    const double eta = friction(I) * std::max(p, p_.pMin) / std::max(gammaDot, p_.gammaDotMin);
    return std::min(eta, p_.etaMax);
}

double MuI::solidFraction(double p, double gammaDot) const { return dilatancy(inertialNumber(p, gammaDot)); }

std::vector<double> MuI::evaluate(const GranularState& s) const {
    const double I = inertialNumber(s.p, s.gammaDot);
    return {I, friction(I), viscosity(s.p, s.gammaDot), dilatancy(I)};
}

}  // namespace granair
