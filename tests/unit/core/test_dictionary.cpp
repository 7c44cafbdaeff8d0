// Dictionary reader: the OpenFOAM-like subset used by the case files, and
// that every error names the file, the key and what was expected.
#include <catch2/catch.hpp>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

using granair::Dictionary;
using granair::InputError;
using Catch::Matchers::Contains;

static const char* kText = R"(
FoamFile { version 2.0; format ascii; class dictionary; object couplingProperties; }
// a comment
couplingInterval 50;   /* block
comment */
gravity (0 0 -9.81);
drag
{
    type ErgunGidaspow;
    switchVoidFraction 0.8;
}
airOn yes;
)";

TEST_CASE("dictionary reads scalars, vectors, words and sub-dictionaries", "[dictionary]") {
    auto d = Dictionary::fromString(kText, "constant/couplingProperties");
    CHECK(d.getInt("couplingInterval") == 50);
    CHECK(d.getVec3("gravity").z() == Approx(-9.81).epsilon(1e-15));
    CHECK(d.subDict("drag").getString("type") == "ErgunGidaspow");
    CHECK(d.subDict("drag").getDouble("switchVoidFraction") == 0.8);
    CHECK(d.getBool("airOn", false));
    CHECK(d.getDouble("missing", 3.5) == 3.5);
    CHECK(d.keys() == std::vector<std::string>{"FoamFile", "couplingInterval", "gravity", "drag", "airOn"});
}

TEST_CASE("dictionary errors name the file, the key path and the expectation", "[dictionary]") {
    auto d = Dictionary::fromString(kText, "constant/couplingProperties");
    CHECK_THROWS_WITH(d.getDouble("nope"),
                      Contains("constant/couplingProperties") && Contains("'nope'") && Contains("missing"));
    CHECK_THROWS_WITH(d.subDict("drag").getDouble("type"),
                      Contains("drag.type") && Contains("expected a number"));
    CHECK_THROWS_WITH(d.getDouble("couplingInterval", 1.0, 10.0),
                      Contains("out of range") && Contains("1 <= couplingInterval <= 10"));
    CHECK_THROWS_WITH(d.getVec3("couplingInterval"), Contains("expected a vector"));
    CHECK_THROWS_AS(d.subDict("gravity"), InputError);
}

TEST_CASE("dictionary syntax errors give the line", "[dictionary]") {
    CHECK_THROWS_WITH(Dictionary::fromString("a 1;\nb { c 2;\n", "f.dict"),
                      Contains("f.dict") && Contains("missing '}'"));
    CHECK_THROWS_WITH(Dictionary::fromString("a 1;\nb 2\n", "f.dict"), Contains("not closed by ';'"));
    CHECK_THROWS_WITH(Dictionary::fromFile("/nonexistent/file"), Contains("cannot open file"));
}

TEST_CASE("NaN and inf are rejected as numbers", "[dictionary]") {
    auto d = Dictionary::fromString("a nan; b inf;", "f");
    CHECK_THROWS_WITH(d.getDouble("a"), Contains("finite"));
    CHECK_THROWS_WITH(d.getDouble("b"), Contains("finite"));
}
