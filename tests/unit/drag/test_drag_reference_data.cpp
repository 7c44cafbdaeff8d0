// The shared data-driven tester of the drag laws (LAMMPS style): every
// registered law must have tests/data/drag/<name>.dat, holding the law's
// dictionary, the fluid, a relative tolerance and points (d eps slip beta).
// The expected beta values come from the law's own script
// tests/data/drag/<name>.py (run by make_reference.py), which evaluates the
// published formulas independently of the C++ code.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "DragTestSupport.hpp"
#include "ModelTestSupport.hpp"
#include "drag/DragLaw.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path dataDir = dragtest::dataDir();

// One reference point: d [m], eps [-], slip [m/s], beta [kg/s].
using Point = std::array<double, 4>;

double number(const std::string& tok, const granair::Dictionary& dict) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (tok.empty() || end != tok.c_str() + tok.size())
        granair::fail<granair::InputError>(dict.where("points"), ": expected a number, found '", tok, "'");
    return v;
}

// points ( (d eps slip beta) ... );
std::vector<Point> readPoints(const granair::Dictionary& dict) {
    const auto& t = dict.tokens("points");
    std::vector<Point> points;
    if (t.size() < 2 || t.front() != "(" || t.back() != ")")
        granair::fail<granair::InputError>(dict.where("points"), ": expected '( (d eps slip beta) ... )'");
    for (size_t i = 1; i + 1 < t.size(); i += 6) {
        if (i + 5 >= t.size() || t[i] != "(" || t[i + 5] != ")")
            granair::fail<granair::InputError>(dict.where("points"), ": expected '(d eps slip beta)' at token ", i);
        points.push_back({number(t[i + 1], dict), number(t[i + 2], dict), number(t[i + 3], dict),
                          number(t[i + 4], dict)});
    }
    return points;
}

}  // namespace

using granair::Dictionary;

TEST_CASE("drag laws: reference data files", "[drag][data]") {
    SECTION("every registered drag law has reference data, and every data file a registered law") {
        modeltest::checkReferenceData(granair::dragLaws(), "drag", dataDir, ".dat", true);
    }

    SECTION("every registered drag law matches its reference data file") {
        const auto& laws = granair::dragLaws();
        for (const auto& name : laws.names()) {
            const fs::path file = dataDir / (name + ".dat");
            INFO("drag law " << name << ", data file " << file.string());
            if (!fs::exists(file)) continue;  // reported by the section above, naming the law

            const Dictionary dict = Dictionary::fromFile(file.string());
            const Dictionary& drag = dict.subDict("drag");
            REQUIRE(drag.getString("type") == name);
            auto law = laws.create(drag);
            REQUIRE(law->name() == name);

            granair::FluidProperties fluid;
            fluid.rho = dict.subDict("fluid").getDouble("rho");
            fluid.mu = dict.subDict("fluid").getDouble("mu");
            const double rtol = dict.getDouble("relativeTolerance");
            REQUIRE(rtol <= 1e-10);  // the brief's tolerance; never loosened per law

            const auto points = readPoints(dict);
            REQUIRE(points.size() >= 3);
            for (const auto& p : points) {
                const double beta = law->beta(p[0], p[1], p[2], fluid);
                INFO("d = " << p[0] << " m, eps = " << p[1] << ", slip = " << p[2] << " m/s: beta = " << beta
                            << " kg/s, expected " << p[3]);
                CHECK(std::abs(beta - p[3]) <= rtol * std::abs(p[3]));
            }
        }
    }
}
