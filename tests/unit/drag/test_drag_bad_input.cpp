// Bad input to the drag laws: every law throws an InputError whose message
// starts with the law and names the bad value (the caller adds the particle).
#include <catch2/catch.hpp>

#include <cmath>

#include "DragTestSupport.hpp"
#include "ModelTestSupport.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "drag/DragLaw.hpp"
#include "drag/ErgunGidaspow.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using granair::Dictionary;
using granair::InputError;

namespace {
const granair::FluidProperties air{1.2, 1.8e-5};
}

TEST_CASE("drag laws: bad input", "[drag][input]") {
    SECTION("drag laws reject bad diameter, void fraction, slip and fluid") {
        for (const auto& name : granair::dragLaws().names()) {
            auto law = dragtest::lawFromData(name);
            const std::string who = "drag law " + name + ": ";
            INFO("drag law " << name);
            CHECK_THROWS_AS(law->beta(-1e-3, 0.5, 1.0, air), InputError);
            CHECK_THROWS_WITH(law->beta(-1e-3, 0.5, 1.0, air), StartsWith(who) && Contains("diameter -0.001"));
            CHECK_THROWS_WITH(law->beta(0.0, 0.5, 1.0, air), Contains("diameter 0 m"));
            CHECK_THROWS_AS(law->beta(1e-3, 0.0, 1.0, air), InputError);
            CHECK_THROWS_WITH(law->beta(1e-3, 0.0, 1.0, air),
                              StartsWith(who) && Contains("void fraction 0 outside (0, 1]"));
            CHECK_THROWS_WITH(law->beta(1e-3, 1.2, 1.0, air),
                              StartsWith(who) && Contains("void fraction 1.2 outside (0, 1]"));
            CHECK_THROWS_WITH(law->beta(1e-3, NAN, 1.0, air), Contains("void fraction nan"));
            CHECK_THROWS_AS(law->beta(1e-3, 0.5, NAN, air), InputError);
            CHECK_THROWS_WITH(law->beta(1e-3, 0.5, NAN, air), StartsWith(who) && Contains("slip velocity nan"));
            CHECK_THROWS_WITH(law->beta(1e-3, 0.5, -1.0, air), Contains("slip velocity -1"));
            CHECK_THROWS_WITH(law->beta(1e-3, 0.5, INFINITY, air), Contains("slip velocity inf"));
            CHECK_THROWS_WITH(law->beta(1e-3, 0.5, 1.0, granair::FluidProperties{NAN, 1.8e-5}),
                              Contains("fluid density nan"));
            CHECK_THROWS_WITH(law->beta(1e-3, 0.5, 1.0, granair::FluidProperties{1.2, 0.0}),
                              Contains("fluid viscosity 0"));
            // force() goes through beta(), so a NaN velocity is caught there too.
            CHECK_THROWS_AS(law->force(1e-3, 0.5, granair::Vec3(NAN, 0, 0), granair::Vec3::Zero(), air), InputError);
        }
    }

    SECTION("an unknown drag law name lists the valid names") {
        const auto dict = Dictionary::fromString("drag { type Ergun; }", "constant/couplingProperties");
        CHECK_THROWS_AS(granair::dragLaws().create(dict.subDict("drag")), InputError);
        CHECK_THROWS_WITH(granair::dragLaws().create(dict.subDict("drag")),
                          Contains("constant/couplingProperties") && Contains("drag.type") &&
                              Contains("unknown drag law 'Ergun'") &&
                              Contains("Known drag law names:" + modeltest::knownNames(granair::dragLaws())));
    }

    SECTION("ErgunGidaspow reads and validates switchVoidFraction") {
        auto create = [](const std::string& text) {
            return granair::dragLaws().create(Dictionary::fromString(text, "case.dict"));
        };
        auto defaulted = create("type ErgunGidaspow;");
        CHECK(dynamic_cast<const granair::ErgunGidaspow&>(*defaulted).switchVoidFraction() == 0.8);
        auto custom = create("type ErgunGidaspow; switchVoidFraction 0.7;");
        CHECK(dynamic_cast<const granair::ErgunGidaspow&>(*custom).switchVoidFraction() == 0.7);
        // switch = 1 is allowed: Ergun everywhere below eps = 1.
        CHECK_NOTHROW(create("type ErgunGidaspow; switchVoidFraction 1;"));

        CHECK_THROWS_WITH(create("type ErgunGidaspow; switchVoidFraction 0;"),
                          Contains("file 'case.dict', key 'switchVoidFraction'") &&
                              Contains("value 0 outside (0, 1]"));
        CHECK_THROWS_WITH(create("type ErgunGidaspow; switchVoidFraction 1.5;"),
                          Contains("switchVoidFraction") && Contains("1.5 outside (0, 1]"));
        CHECK_THROWS_AS(create("type ErgunGidaspow; switchVoidFraction high;"), InputError);
        CHECK_THROWS_AS(granair::ErgunGidaspow(-0.1), InputError);
    }
}
