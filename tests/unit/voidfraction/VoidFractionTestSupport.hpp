// VoidFractionTestSupport.hpp: shared helpers of the void-fraction tests:
// a portable random source, models from their data files, stencil checks.
#pragma once
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/Dictionary.hpp"
#include "mapping/CellLocator.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace vftest {

// Uniform doubles from mt19937_64, whose output sequence the C++ standard fixes
// (std::uniform_real_distribution is implementation-defined), so a seed gives
// the same particles with any standard library.
class Random {
public:
    explicit Random(std::uint64_t seed) : g_(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * ((g_() >> 11) * 0x1.0p-53); }

private:
    std::mt19937_64 g_;
};

inline std::string dataDir() { return std::string(GRANAIR_TEST_DATA_DIR) + "/voidfraction"; }
inline std::string dataFile(const std::string& type) { return dataDir() + "/" + type + ".dict"; }

// The model `type` with the parameters in tests/data/voidfraction/<type>.dict;
// a registered model without a data file fails the test.
inline std::unique_ptr<granair::VoidFractionModel> modelFromData(const std::string& type) {
    const std::string file = dataFile(type);
    INFO("void-fraction model " << type << " is registered but has no parameter file " << file
                                 << " (docs/adding-a-model.md)");
    REQUIRE(std::ifstream(file).good());
    const auto dict = granair::Dictionary::fromFile(file);
    REQUIRE(dict.getString("type") == type);
    return granair::voidFractionModels().create(dict);
}

// Interface contract of a stencil: local cells, each once, weights >= 0
// summing to 1. Tolerance 1e-12: a sum of at most ~10^3 terms each rounded
// to 1.1e-16 relative.
inline void checkStencil(const granair::CellLocator& mesh, const std::vector<granair::CellWeight>& st) {
    REQUIRE(!st.empty());
    double sum = 0;
    std::vector<int> cells;
    for (const auto& cw : st) {
        REQUIRE(cw.cell >= 0);
        REQUIRE(cw.cell < mesh.nCells());
        REQUIRE(cw.weight >= 0);
        sum += cw.weight;
        cells.push_back(cw.cell);
    }
    std::sort(cells.begin(), cells.end());
    CHECK(std::adjacent_find(cells.begin(), cells.end()) == cells.end());
    CHECK(sum == Approx(1.0).margin(1e-12));
}

// Weight of `cell` in a stencil (0 if absent).
inline double weightOf(const std::vector<granair::CellWeight>& st, int cell) {
    double w = 0;
    for (const auto& cw : st)
        if (cw.cell == cell) w += cw.weight;
    return w;
}

}  // namespace vftest
