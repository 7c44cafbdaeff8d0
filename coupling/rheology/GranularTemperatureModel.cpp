// GranularTemperatureModel.cpp: see GranularTemperatureModel.hpp.
#include "rheology/GranularTemperatureModel.hpp"

#include <cmath>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace granair {

GranularTemperatureModel::GranularTemperatureModel(const LatzSchmidt& closure, const Parameters& p)
    : closure_(closure), p_(p) {
    auto check = [](bool good, const char* key, double v, const char* expected) {
        if (!good) failParameter(key, "rheology latzSchmidt: ", key, " = ", v, ", expected ", expected);
    };
    check(p_.rhoP > 0 && std::isfinite(p_.rhoP), "rhoP", p_.rhoP, "a finite particle density > 0 [kg/m3]");
    check(p_.etaMax > 0 && std::isfinite(p_.etaMax), "etaMax", p_.etaMax, "a finite viscosity cap > 0 [Pa s]");
    check(p_.TMin > 0 && std::isfinite(p_.TMin), "TMin", p_.TMin, "a finite temperature floor > 0 [m2/s2]");
}

GranularTemperatureModel GranularTemperatureModel::fromDictionary(const Dictionary& dict) {
    // The closure is the registry's latzSchmidt (its keys checked there), not a second construction path.
    const auto closure = rheologies().create(dict);
    const auto* ls = dynamic_cast<const LatzSchmidt*>(closure.get());
    if (!ls)
        fail<InputError>(dict.where("type"), ": the granular-temperature equation needs rheology '",
                         LatzSchmidt::typeName, "', got '", closure->name(), "'");
    Parameters p;
    p.rhoP = dict.getDouble("rhoP");
    p.etaMax = dict.getDouble("etaMax", p.etaMax);
    p.TMin = dict.getDouble("TMin", p.TMin);
    return constructNamingKey(dict, [&] { return GranularTemperatureModel(*ls, p); });
}

GranularTemperatureModel::Cell GranularTemperatureModel::evaluate(double p, double T, double gammaDot) const {
    if (!(std::isfinite(gammaDot) && gammaDot >= 0))
        fail<InputError>("rheology latzSchmidt: shear rate ", gammaDot, " 1/s, expected a finite gammaDot >= 0");
    // solidFraction checks p (finite) and T (finite, > 0).
    Cell cell;
    cell.c = closure_.solidFraction(p / p_.rhoP, T);
    const LatzSchmidt::Values v = closure_.values(cell.c, T);
    const double nuMax = p_.etaMax / p_.rhoP;
    cell.capped = v.eta > nuMax;
    const double k = cell.capped ? nuMax / v.eta : 1.0;
    cell.eta = p_.rhoP * k * v.eta;
    cell.lambda = k * v.lambda;
    cell.production = k * v.eta * gammaDot * gammaDot;
    cell.dissipation = v.epsR * v.pK;
    cell.sinkRate = cell.dissipation / T;
    return cell;
}

}  // namespace granair
