// The shared data-driven tester of the rheologies (LAMMPS style): every
// registered rheology must have tests/data/rheology/<name>.dat (variants of
// its parameters in <name>.<variant>.dat), each holding the rheology's
// dictionary, a relative tolerance, the input and output names, and points.
// The expected values come from the model's own script
// tests/data/rheology/<name>.py (run by make_reference.py), which evaluates
// the published formulas independently of the C++ code.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "ModelTestSupport.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "rheology/MuI.hpp"
#include "rheology/Rheology.hpp"

namespace fs = std::filesystem;
using granair::Dictionary;
using granair::InputError;

namespace {

const fs::path dataDir = fs::path(GRANAIR_TEST_DATA_DIR) / "rheology";

double number(const std::string& tok, const Dictionary& dict) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (tok.empty() || end != tok.c_str() + tok.size())
        granair::fail<InputError>(dict.where("points"), ": expected a number, found '", tok, "'");
    return v;
}

// key ( a b c );
std::vector<std::string> nameList(const Dictionary& dict, const std::string& key) {
    const auto& t = dict.tokens(key);
    if (t.size() < 3 || t.front() != "(" || t.back() != ")")
        granair::fail<InputError>(dict.where(key), ": expected '( name ... )'");
    return {t.begin() + 1, t.end() - 1};
}

// points ( (x1 .. xn) ... ); with n values per point.
std::vector<std::vector<double>> readPoints(const Dictionary& dict, size_t n) {
    const auto& t = dict.tokens("points");
    std::vector<std::vector<double>> points;
    if (t.size() < 2 || t.front() != "(" || t.back() != ")")
        granair::fail<InputError>(dict.where("points"), ": expected '( (values) ... )'");
    for (size_t i = 1; i + 1 < t.size(); i += n + 2) {
        if (i + n + 1 >= t.size() || t[i] != "(" || t[i + n + 1] != ")")
            granair::fail<InputError>(dict.where("points"), ": expected ", n, " values per point at token ", i);
        std::vector<double> p;
        for (size_t k = 1; k <= n; ++k) p.push_back(number(t[i + k], dict));
        points.push_back(p);
    }
    return points;
}

void setInput(granair::GranularState& s, const std::string& name, double v) {
    if (name == "p") s.p = v;
    else if (name == "gammaDot") s.gammaDot = v;
    else if (name == "c") s.c = v;
    else if (name == "T") s.T = v;
    else FAIL("unknown input '" << name << "' in a rheology data file");
}

}  // namespace

TEST_CASE("rheologies: reference data files", "[rheology][data]") {
    SECTION("every rheology data file matches the model it names") {
        int files = 0;
        for (const auto& e : fs::directory_iterator(dataDir)) {
            if (e.path().extension() != ".dat") continue;
            ++files;
            const std::string model = modeltest::modelOf(e.path());
            INFO("data file " << e.path().string());
            REQUIRE(granair::rheologies().has(model));

            const Dictionary dict = Dictionary::fromFile(e.path().string());
            const Dictionary& params = dict.subDict("rheology");
            REQUIRE(params.getString("type") == model);
            const auto r = granair::rheologies().create(params);
            REQUIRE(r->name() == model);
            const double rtol = dict.getDouble("relativeTolerance");
            REQUIRE(rtol <= 1e-12);  // the brief's tolerance; never loosened per model

            // The file's inputs are exactly the model's; its outputs are among the model's.
            const auto inputs = nameList(dict, "inputs");
            const auto outputNames = nameList(dict, "outputs");
            const auto modelInputs = r->inputs();
            REQUIRE(std::set<std::string>(inputs.begin(), inputs.end()) ==
                    std::set<std::string>(modelInputs.begin(), modelInputs.end()));
            std::vector<size_t> column;
            const auto outs = r->outputs();
            for (const auto& name : outputNames) {
                size_t k = 0;
                while (k < outs.size() && outs[k].name != name) ++k;
                INFO("output " << name);
                REQUIRE(k < outs.size());
                column.push_back(k);
            }

            const auto points = readPoints(dict, inputs.size() + outputNames.size());
            REQUIRE(points.size() >= 5);
            for (const auto& pt : points) {
                granair::GranularState s;
                for (size_t k = 0; k < inputs.size(); ++k) setInput(s, inputs[k], pt[k]);
                const auto got = r->evaluate(s);
                REQUIRE(got.size() == outs.size());
                for (size_t k = 0; k < outputNames.size(); ++k) {
                    const double expected = pt[inputs.size() + k];
                    const double value = got[column[k]];
                    INFO("at (" << pt[0] << ", " << pt[1] << "): " << outputNames[k] << " = " << value << " "
                                << outs[column[k]].unit << ", expected " << expected);
                    CHECK(std::abs(value - expected) <= rtol * std::abs(expected));
                }
            }
        }
        CHECK(files >= static_cast<int>(granair::rheologies().names().size()));
    }

    SECTION("every registered rheology has reference data, and every data file a registered rheology") {
        modeltest::checkReferenceData(granair::rheologies(), "rheology", dataDir, ".dat", true);
    }

    SECTION("barkerGray2017: I1 is the lower well-posedness root of the Jop form") {
        const Dictionary dict = Dictionary::fromFile((dataDir / "muI.barkerGray2017.dat").string());
        const auto r = granair::rheologies().create(dict.subDict("rheology"));
        const auto& m = dynamic_cast<const granair::MuI&>(*r);
        // I1 from an independent bisection in make_reference.py; both resolve
        // the root to machine precision.
        CHECK(m.regularisationI1() == Approx(dict.getDouble("regularisationI1")).epsilon(1e-12));
    }
}
