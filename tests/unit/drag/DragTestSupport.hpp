// DragTestSupport.hpp: the drag laws as the shared tests see them: every
// registered law, built from the `drag` dictionary of its reference data
// file tests/data/drag/<name>.dat, so a new law (with parameters or without)
// is covered by every test that loops over the registry.
#pragma once
#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>

#include "core/Dictionary.hpp"
#include "drag/DragLaw.hpp"

namespace dragtest {

inline std::filesystem::path dataDir() { return std::filesystem::path(GRANAIR_TEST_DATA_DIR) / "drag"; }
inline std::filesystem::path dataFile(const std::string& name) { return dataDir() / (name + ".dat"); }

// The registered law `name` with the parameters of its data file; a law
// without a data file fails the calling test, naming the law.
inline std::unique_ptr<granair::DragLaw> lawFromData(const std::string& name) {
    const auto file = dataFile(name);
    INFO("drag law " << name << " is registered but has no reference data file " << file.string()
                     << " (docs/adding-a-model.md)");
    REQUIRE(std::filesystem::exists(file));
    return granair::dragLaws().create(granair::Dictionary::fromFile(file.string()).subDict("drag"));
}

}  // namespace dragtest
