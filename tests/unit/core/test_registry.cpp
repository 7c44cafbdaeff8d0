// Registry: models by name; an unknown name lists the valid ones, sorted; a
// bad parameter value a model's constructor reports names the file and key.
#include <catch2/catch.hpp>

#include "core/Registry.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

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
// A model in the form the families use: typeName, fromDictionary, and a
// constructor that checks its parameter with a ParameterError.
struct Positive : Model {
    static constexpr const char* typeName = "positive";
    double k;
    explicit Positive(double kIn) : k(kIn) {
        if (!(k > 0)) granair::failParameter("k", "test model positive: k = ", k, ", expected k > 0");
    }
    static std::unique_ptr<Model> fromDictionary(const granair::Dictionary& d) {
        return std::make_unique<Positive>(d.getDouble("k"));
    }
    double value() const override { return k; }
};
struct One : Model {
    static constexpr const char* typeName = "one";
    static std::unique_ptr<Model> fromDictionary(const granair::Dictionary&) { return std::make_unique<One>(); }
    double value() const override { return 1; }
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
    CHECK_THROWS_WITH(reg.create(bad), Contains("unknown test model 'three'") && Contains("scaled\n    two") &&
                                           Contains("case.dict"));
    CHECK_THROWS(reg.add("two", [](const granair::Dictionary&) { return std::make_unique<Two>(); }));
}

TEST_CASE("registry from a model list; parameter errors name the file and the bad key", "[registry]") {
    const auto reg = granair::makeRegistry<Model>("test model", granair::ModelList<Positive, One>{});
    CHECK(reg.names() == std::vector<std::string>{"one", "positive"});
    CHECK(reg.create(granair::Dictionary::fromString("type positive; k 3;", "case.dict"))->value() == 3);

    const auto top = granair::Dictionary::fromString("model { type positive; k -1; }", "case.dict");
    CHECK_THROWS_AS(reg.create(top.subDict("model")), granair::InputError);
    CHECK_THROWS_WITH(reg.create(top.subDict("model")),
                      StartsWith("file 'case.dict', key 'model.k': test model positive: k = -1, expected k > 0"));
    // A dictionary error (missing key) passes unchanged: it names the file and key already.
    CHECK_THROWS_WITH(reg.create(granair::Dictionary::fromString("type positive;", "case.dict")),
                      StartsWith("file 'case.dict', key 'k': missing"));
    // Outside a registry the constructor's error is an InputError naming the model and key.
    CHECK_THROWS_AS(Positive(0.0), granair::InputError);
    CHECK_THROWS_WITH(Positive(0.0), StartsWith("test model positive: k = 0"));
    // A listed model twice is a programming error, reported at once.
    CHECK_THROWS_WITH((granair::makeRegistry<Model>("test model", granair::ModelList<One, One>{})),
                      Contains("duplicate test model 'one'"));
}
