// Registry: models by name; an unknown name lists the valid ones, sorted.
#include <catch2/catch.hpp>

#include "core/Registry.hpp"

namespace {
struct Model {
    virtual ~Model() = default;
    virtual double value() const = 0;
};
struct Two : Model {
    double value() const override { return 2; }
};
struct Scaled : Model {
    double k;
    explicit Scaled(const granair::Dictionary& d) : k(d.getDouble("k")) {}
    double value() const override { return k; }
};
}  // namespace

TEST_CASE("registry creates by name and lists valid names on error", "[registry]") {
    granair::Registry<Model> reg("test model");
    reg.add("two", [](const granair::Dictionary&) { return std::make_unique<Two>(); });
    reg.add("scaled", [](const granair::Dictionary& d) { return std::make_unique<Scaled>(d); });
    CHECK(reg.names() == std::vector<std::string>{"scaled", "two"});

    auto d = granair::Dictionary::fromString("type scaled; k 7;", "case.dict");
    CHECK(reg.create(d)->value() == 7);

    auto bad = granair::Dictionary::fromString("type three;", "case.dict");
    CHECK_THROWS_WITH(reg.create(bad), Catch::Matchers::Contains("unknown test model 'three'") &&
                                           Catch::Matchers::Contains("scaled\n    two") &&
                                           Catch::Matchers::Contains("case.dict"));
    CHECK_THROWS(reg.add("two", [](const granair::Dictionary&) { return std::make_unique<Two>(); }));
}
