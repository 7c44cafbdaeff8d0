// ModelTestSupport.hpp: what every model family's shared tests check about
// the registry and the reference data (drag, voidfraction, rheology).
//
// The tests never list model names: they take them from the registry, so a
// new model (docs/adding-a-model.md) is tested by adding it, and a
// registered model without reference data fails here, naming the model.
#pragma once
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "core/Registry.hpp"

namespace modeltest {

// The valid names as Registry::create lists them after an unknown name.
template <class Base>
std::string knownNames(const granair::Registry<Base>& registry) {
    std::string list;
    for (const auto& n : registry.names()) list += "\n    " + n;
    return list;
}

// The model a data file belongs to: its file name up to the first '.'
// (muI.dat and muI.barkerGray2017.dat both belong to muI).
inline std::string modelOf(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    return name.substr(0, name.find('.'));
}

// Both directions between the registry and the data folder `dir`:
//   - every registered model has dir/<name><extension> and, when
//     `generator` is set, its reference script dir/<name>.py;
//   - every dir/*<extension> file belongs to a registered model.
// `family` is the registry's folder (coupling/<family>/sources.cmake holds its list).
template <class Base>
void checkReferenceData(const granair::Registry<Base>& registry, const std::string& family,
                        const std::filesystem::path& dir, const std::string& extension, bool generator) {
    namespace fs = std::filesystem;
    REQUIRE(!registry.names().empty());
    for (const auto& name : registry.names()) {
        const fs::path data = dir / (name + extension);
        if (!fs::exists(data))
            FAIL_CHECK(registry.family() << " '" << name << "' is registered but has no reference data "
                                         << data.string() << " (every model needs it: docs/adding-a-model.md)");
        const fs::path script = dir / (name + ".py");
        if (generator && !fs::exists(script))
            FAIL_CHECK(registry.family() << " '" << name << "' has no reference script " << script.string()
                                         << " (it computes " << name << extension
                                         << " from the published formulas: docs/adding-a-model.md)");
    }
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().filename().string().size() <= extension.size() ||
            e.path().string().compare(e.path().string().size() - extension.size(), extension.size(), extension) != 0)
            continue;
        if (!registry.has(modelOf(e.path())))
            FAIL_CHECK("data file " << e.path().string() << " belongs to no registered " << registry.family() << " '"
                                    << modelOf(e.path()) << "': add the model's class to the list in coupling/"
                                    << family << "/sources.cmake, or remove the file");
    }
}

}  // namespace modeltest
