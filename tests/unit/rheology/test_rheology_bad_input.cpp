// Bad input to the rheologies: an InputError whose message names the model
// and the bad value (state) or the file and key (parameters); an unknown name
// lists the valid ones.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "ModelTestSupport.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "rheology/LatzSchmidt.hpp"
#include "rheology/MuI.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using granair::Dictionary;
using granair::InputError;

namespace {

const std::string mcc = "type muI; muS 0.401; mu2 0.908; I0 0.0465; d 660e-6; rhoP 1500;";
const std::string lactose =
    "type latzSchmidt; c0 0.5579; cMax 0.5771; T0 0.41; eta0 0.00052; lambda0 0.001; eps0 332.84;";

std::unique_ptr<granair::Rheology> create(const std::string& text) {
    return granair::rheologies().create(Dictionary::fromString(text, "constant/granularProperties"));
}

}  // namespace

TEST_CASE("rheologies: bad input", "[rheology][input]") {
    SECTION("an unknown rheology name lists the valid names") {
        const auto dict = Dictionary::fromString("rheology { type muOfI; }", "constant/granularProperties");
        CHECK_THROWS_AS(granair::rheologies().create(dict.subDict("rheology")), InputError);
        CHECK_THROWS_WITH(granair::rheologies().create(dict.subDict("rheology")),
                          Contains("constant/granularProperties") && Contains("rheology.type") &&
                              Contains("unknown rheology 'muOfI'") &&
                              Contains("Known rheology names:" + modeltest::knownNames(granair::rheologies())));
    }

    SECTION("muI rejects a bad state, naming the value") {
        const auto r = create(mcc);
        const auto& m = dynamic_cast<const granair::MuI&>(*r);
        CHECK_THROWS_AS(m.viscosity(NAN, 1.0), InputError);
        CHECK_THROWS_WITH(m.viscosity(NAN, 1.0), StartsWith("rheology muI: pressure nan Pa"));
        CHECK_THROWS_WITH(m.viscosity(INFINITY, 1.0), Contains("pressure inf Pa"));
        CHECK_THROWS_WITH(m.viscosity(100.0, -0.5), StartsWith("rheology muI: shear rate -0.5 1/s"));
        CHECK_THROWS_WITH(m.viscosity(100.0, NAN), Contains("shear rate nan"));
        CHECK_THROWS_WITH(m.friction(-1.0), Contains("inertial number -1"));
        // evaluate() of a state without p (e.g. filled for another model) is caught too.
        granair::GranularState s;
        s.c = 0.5;
        s.T = 1.0;
        CHECK_THROWS_WITH(r->evaluate(s), Contains("pressure nan"));
    }

    SECTION("muI rejects bad parameters, naming the file and key") {
        CHECK_THROWS_WITH(create("type muI; mu2 0.9; I0 0.05; d 1e-3; rhoP 1500;"),
                          Contains("constant/granularProperties") && Contains("muS"));
        // A value out of range names its own key (not the type key).
        CHECK_THROWS_WITH(create("type muI; muS 0.5; mu2 0.4; I0 0.05; d 1e-3; rhoP 1500;"),
                          StartsWith("file 'constant/granularProperties', key 'mu2': rheology muI: mu2 = 0.4") &&
                              Contains("mu_2 > mu_s"));
        const auto nested = Dictionary::fromString("rheology { " + mcc + " pMin 0; }", "constant/granularProperties");
        CHECK_THROWS_WITH(granair::rheologies().create(nested.subDict("rheology")),
                          StartsWith("file 'constant/granularProperties', key 'rheology.pMin': ") &&
                              Contains("pMin = 0"));
        CHECK_THROWS_WITH(create(mcc + "etaMax -3;"), Contains("etaMax = -3"));
        CHECK_THROWS_WITH(create(mcc + "pMin 0;"), Contains("pMin = 0"));
        CHECK_THROWS_WITH(create(mcc + "gammaDotMin 0;"), Contains("gammaDotMin = 0"));
        CHECK_THROWS_WITH(create(mcc + "phiMin 0.7;"), Contains("phiMin = 0.7"));
        // (a key given twice is an error of its own: d replaced, not repeated)
        CHECK_THROWS_WITH(create("type muI; muS 0.401; mu2 0.908; I0 0.0465; d 0; rhoP 1500;"), Contains("d = 0"));
        CHECK_THROWS_WITH(create(mcc + "regularisation gray;"),
                          Contains("regularisation") && Contains("unknown regularisation 'gray'") &&
                              Contains("none barkerGray2017"));
        CHECK_THROWS_WITH(create(mcc + "regularisation barkerGray2017; alphaReg 2.5;"),
                          Contains("key 'alphaReg'") && Contains("alphaReg = 2.5") && Contains("ill posed"));
        CHECK_THROWS_WITH(create(mcc + "regularisation barkerGray2017; muInf -1;"), Contains("muInf = -1"));
        CHECK_THROWS_AS(create(mcc + "I0 fast;"), InputError);
    }

    SECTION("latzSchmidt rejects c outside [0, c_max) and T <= 0, naming the value") {
        const auto r = create(lactose);
        const auto& ls = dynamic_cast<const granair::LatzSchmidt&>(*r);
        CHECK_THROWS_AS(ls.values(0.5771, 1.0), InputError);
        CHECK_THROWS_WITH(ls.values(0.5771, 1.0),
                          StartsWith("rheology latzSchmidt: solid volume fraction c = 0.5771 outside [0, cMax"));
        CHECK_THROWS_WITH(ls.values(0.6, 1.0), Contains("c = 0.6 outside"));
        CHECK_THROWS_WITH(ls.values(-0.01, 1.0), Contains("c = -0.01 outside"));
        CHECK_THROWS_WITH(ls.values(NAN, 1.0), Contains("c = nan"));
        CHECK_THROWS_WITH(ls.values(0.5, 0.0), StartsWith("rheology latzSchmidt: granular temperature T = 0 m2/s2"));
        CHECK_THROWS_WITH(ls.values(0.5, -2.0), Contains("T = -2 m2/s2"));
        CHECK_THROWS_WITH(ls.values(0.5, NAN), Contains("T = nan"));
        CHECK_THROWS_WITH(ls.values(0.5, INFINITY), Contains("T = inf"));
    }

    SECTION("latzSchmidt rejects bad parameters, naming the file and key") {
        CHECK_THROWS_WITH(create("type latzSchmidt; c0 0.6; cMax 0.58; T0 0.41; eta0 5e-4; lambda0 1e-3; eps0 300;"),
                          StartsWith("file 'constant/granularProperties', key 'cMax': ") && Contains("cMax = 0.58"));
        CHECK_THROWS_WITH(create("type latzSchmidt; c0 0.5; cMax 0.58; T0 -1; eta0 5e-4; lambda0 1e-3; eps0 300;"),
                          Contains("T0 = -1"));
        CHECK_THROWS_WITH(create("type latzSchmidt; c0 0.5; cMax 0.58; T0 0.4; lambda0 1e-3; eps0 300;"),
                          Contains("eta0"));
    }
}
