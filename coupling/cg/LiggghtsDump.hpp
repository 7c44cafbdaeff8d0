// LiggghtsDump.hpp: read LIGGGHTS / LAMMPS text dumps (`dump custom`, `dump local`).
//
// A dump file holds one or more frames:
//     ITEM: TIMESTEP / <step>
//     ITEM: NUMBER OF ATOMS (or ENTRIES) / <rows>
//     ITEM: BOX BOUNDS pp ff ff / <xlo xhi> / <ylo yhi> / <zlo zhi>
//     ITEM: ATOMS id x y ... (or ITEM: ENTRIES c_ID[1] ...) / <rows lines>
// A series is a set of files given by a glob pattern (one file per snapshot,
// as `dump ... file_*.dump` writes, or one file with every frame, or both);
// frames are indexed by time step once, then read on demand, so memory holds
// one snapshot at a time. Every error names the file, the frame's time step
// or the line, and what was expected. The reader is plain C++ (no LIGGGHTS).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "cg/CgSnapshot.hpp"

namespace granair {

struct DumpFrame {
    std::string file;
    long step = 0;
    CgDomain domain;
    std::vector<std::string> columns;  // names from the ATOMS / ENTRIES line
    std::size_t rows = 0;
    std::vector<double> data;  // rows x columns, row-major

    // Index of a column by name, -1 if absent.
    int column(const std::string& name) const;
    double at(std::size_t row, int col) const { return data[row * columns.size() + col]; }
    std::string where() const;  // "file 'x' (time step N)"
};

class LiggghtsDumpSeries {
public:
    // pattern: a file name or a glob pattern; what: "particle dump", ... for messages.
    LiggghtsDumpSeries(const std::string& pattern, std::string what);

    std::vector<long> steps() const;
    bool has(long step) const { return index_.count(step) > 0; }
    DumpFrame read(long step) const;
    const std::string& pattern() const { return pattern_; }
    const std::string& what() const { return what_; }

private:
    struct Location {
        std::string file;
        long offset;  // byte offset of the frame's "ITEM: TIMESTEP"
        long line;    // its line number, for messages
    };
    void scan(const std::string& file);
    std::string pattern_, what_;
    std::map<long, Location> index_;
};

}  // namespace granair
