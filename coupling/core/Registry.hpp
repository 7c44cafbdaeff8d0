// Registry.hpp: models chosen by name from the case files.
//
// One registry per model family (drag laws, void-fraction models, ...). Each
// family fills its registry in ONE explicit function (registerDragLaws, ...),
// not by static initialisers, which a static link can silently drop. An
// unknown name fails with the sorted list of valid names, OpenFOAM-style.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace granair {

template <class Base>
class Registry {
public:
    // A factory reads the model's own parameters from its dictionary.
    using Factory = std::function<std::unique_ptr<Base>(const Dictionary&)>;

    explicit Registry(std::string family) : family_(std::move(family)) {}

    void add(const std::string& name, Factory f) {
        if (factories_.count(name)) fail("duplicate ", family_, " '", name, "' registered");
        factories_[name] = std::move(f);
    }

    bool has(const std::string& name) const { return factories_.count(name) > 0; }

    std::vector<std::string> names() const {
        std::vector<std::string> n;
        for (const auto& kv : factories_) n.push_back(kv.first);
        return n;  // std::map keeps them sorted
    }

    // Create the model named by `dict.<key>`, passing `dict` for its parameters.
    std::unique_ptr<Base> create(const Dictionary& dict, const std::string& key = "type") const {
        const std::string name = dict.getString(key);
        auto it = factories_.find(name);
        if (it == factories_.end()) {
            std::string list;
            for (const auto& n : names()) list += "\n    " + n;
            fail<InputError>(dict.where(key), ": unknown ", family_, " '", name, "'. Known ", family_,
                             " names:", list);
        }
        return it->second(dict);
    }

    const std::string& family() const { return family_; }

private:
    std::string family_;
    std::map<std::string, Factory> factories_;
};

}  // namespace granair
