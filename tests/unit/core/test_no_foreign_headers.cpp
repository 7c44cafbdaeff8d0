// coupling/ must stay free of OpenFOAM and LIGGGHTS so it can be reused and
// tested alone: scan its sources for their headers.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

TEST_CASE("coupling/ includes no OpenFOAM or LIGGGHTS header", "[architecture]") {
    namespace fs = std::filesystem;
    const std::regex foreign(
        R"(#\s*include\s*[<"](fvCFD|fvMesh|volFields|surfaceFields|IOdictionary|lammps|library|atom|fix_external|modify|input)\.(H|h)[>"])");
    int scanned = 0;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(GRANAIR_SOURCE_DIR) / "coupling")) {
        if (!e.is_regular_file()) continue;
        const auto ext = e.path().extension();
        if (ext != ".hpp" && ext != ".cpp") continue;
        std::ifstream in(e.path());
        std::string line;
        int n = 0;
        while (std::getline(in, line)) {
            ++n;
            INFO(e.path().string() << ":" << n << ": " << line);
            CHECK_FALSE(std::regex_search(line, foreign));
        }
        ++scanned;
    }
    CHECK(scanned > 0);
}
