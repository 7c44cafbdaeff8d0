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

TEST_CASE("unknown keys name the file, the line and the closest known key", "[dictionary]") {
    auto d = Dictionary::fromString("FoamFile { version 2.0; }\ncouplingIntervall 50;\nair on;\n"
                                    "drag { type ErgunGidaspow; swichVoidFraction 0.8; }\n",
                                    "constant/couplingProperties");
    d.getDouble("couplingInterval", 1.0);  // asked for, with a default
    d.getBool("air", true);
    CHECK_THROWS_WITH(d.checkKnownKeys(), Contains("constant/couplingProperties' line 2") &&
                                              Contains("unknown key 'couplingIntervall'") &&
                                              Contains("did you mean 'couplingInterval'"));
    d.allow({"couplingIntervall"});
    // sub-dictionaries a reader looked into are checked too
    d.subDict("drag").getString("type");
    d.subDict("drag").getDouble("switchVoidFraction", 0.8);
    CHECK_THROWS_WITH(d.checkKnownKeys(), Contains("line 4") && Contains("unknown key 'drag.swichVoidFraction'") &&
                                              Contains("did you mean 'switchVoidFraction'"));
    d.subDict("drag").allow({"swichVoidFraction"});
    CHECK_NOTHROW(d.checkKnownKeys());
}

TEST_CASE("a sub-dictionary nobody reads is not checked; keys() accepts every key", "[dictionary]") {
    auto d = Dictionary::fromString("a 1; monitors { x { type plane; } } names { p 1; q 2; }", "f");
    d.getDouble("a");
    d.allow({"monitors"});
    d.subDict("names").keys();
    CHECK_NOTHROW(d.checkKnownKeys());
}

TEST_CASE("a key given twice is an error with both lines", "[dictionary]") {
    CHECK_THROWS_WITH(Dictionary::fromString("a 1;\nb 2;\na 3;\n", "f.dict"),
                      Contains("f.dict' line 3") && Contains("key 'a' given twice (first on line 1)"));
    CHECK_THROWS_WITH(Dictionary::fromString("s { a 1; }\ns { b 1; }\n", "f.dict"),
                      Contains("line 2") && Contains("key 's' given twice"));
    CHECK_THROWS_WITH(Dictionary::fromString("d { x 1;\n x 2; }", "f.dict"), Contains("key 'd.x' given twice"));
}

TEST_CASE("a missing ';' is named with its line", "[dictionary]") {
    auto d = Dictionary::fromString("couplingInterval 50\nair on;\n", "cp");
    CHECK_THROWS_WITH(d.getDouble("couplingInterval"),
                      Contains("cp', key 'couplingInterval' (line 1)") && Contains("found '50 air on'") &&
                          Contains("';' missing at the end of line 1"));
    CHECK_THROWS_WITH(Dictionary::fromString("a 1\nb { c 2; }\n", "cp"),
                      Contains("line 2") && Contains("entry 'a' (line 1)") && Contains("';' missing at the end of line 1"));
}

TEST_CASE("a NaN vector says which component", "[dictionary]") {
    auto d = Dictionary::fromString("gravity (0 nan -9.81);\n", "cp");
    CHECK_THROWS_WITH(d.getVec3("gravity"), Contains("key 'gravity' (line 1)") && Contains("component y") &&
                                                Contains("'nan'") && Contains("finite"));
}
