// LiggghtsDump.cpp: see LiggghtsDump.hpp.
#include "cg/LiggghtsDump.hpp"

#include <glob.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"

namespace granair {

namespace {

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::vector<std::string> words(const std::string& s) {
    std::istringstream is(s);
    std::vector<std::string> w;
    for (std::string t; is >> t;) w.push_back(t);
    return w;
}

long parseLong(const std::string& s, const std::string& file, long line, const char* what) {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(s.c_str(), &end, 10);
    while (end && (*end == ' ' || *end == '\t' || *end == '\r')) ++end;
    if (errno || end == s.c_str() || (end && *end))
        fail<InputError>("file '", file, "' line ", line, ": expected ", what, ", found '", s, "'");
    return v;
}

// Reads the header of the frame starting at the stream position; on return
// the stream stands at its first data row.
struct Header {
    long step = 0;
    std::size_t rows = 0;
    CgDomain domain;
    std::vector<std::string> columns;
};

Header readHeader(std::istream& in, const std::string& file, long& line) {
    Header h;
    std::string s;
    bool haveStep = false, haveRows = false, haveBox = false;
    while (std::getline(in, s)) {
        ++line;
        if (!s.empty() && s.back() == '\r') s.pop_back();
        if (s.empty()) continue;
        if (startsWith(s, "ITEM: TIMESTEP")) {
            if (!std::getline(in, s)) break;
            ++line;
            h.step = parseLong(s, file, line, "a time step number");
            haveStep = true;
        } else if (startsWith(s, "ITEM: NUMBER OF")) {
            if (!std::getline(in, s)) break;
            ++line;
            const long n = parseLong(s, file, line, "a row count");
            if (n < 0) fail<InputError>("file '", file, "' line ", line, ": negative row count ", n);
            h.rows = std::size_t(n);
            haveRows = true;
        } else if (startsWith(s, "ITEM: BOX BOUNDS")) {
            const auto w = words(s);
            if (w.size() != 6)
                fail<InputError>("file '", file, "' line ", line, ": '", s,
                                 "': expected ITEM: BOX BOUNDS with three boundary flags "
                                 "(a triclinic box is not supported)");
            for (int a = 0; a < 3; ++a) {
                h.domain.periodic[a] = w[3 + a] == "pp";
                if (!std::getline(in, s)) fail<InputError>("file '", file, "': ends inside BOX BOUNDS");
                ++line;
                std::istringstream is(s);
                if (!(is >> h.domain.box.lo[a] >> h.domain.box.hi[a]) || !(h.domain.box.hi[a] >= h.domain.box.lo[a]))
                    fail<InputError>("file '", file, "' line ", line, ": expected two box bounds lo <= hi, found '",
                                     s, "'");
            }
            haveBox = true;
        } else if (startsWith(s, "ITEM: ATOMS") || startsWith(s, "ITEM: ENTRIES")) {
            auto w = words(s);
            h.columns.assign(w.begin() + 2, w.end());
            if (!haveStep || !haveRows || !haveBox)
                fail<InputError>("file '", file, "' line ", line, ": column line before the frame's TIMESTEP, ",
                                 "NUMBER OF and BOX BOUNDS items: not a LIGGGHTS text dump");
            if (h.columns.empty())
                fail<InputError>("file '", file, "' line ", line, ": no column names after '", w[0], " ", w[1],
                                 "'");
            return h;
        } else {
            fail<InputError>("file '", file, "' line ", line, ": unexpected '", s.substr(0, 60),
                             "' (expected an ITEM: line of a LIGGGHTS text dump)");
        }
    }
    fail<InputError>("file '", file, "': ends inside a frame header (line ", line, ")");
}

}  // namespace

int DumpFrame::column(const std::string& name) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c] == name) return int(c);
    return -1;
}

std::string DumpFrame::where() const {
    std::ostringstream os;
    os << "file '" << file << "' (time step " << step << ")";
    return os.str();
}

LiggghtsDumpSeries::LiggghtsDumpSeries(const std::string& pattern, std::string what)
    : pattern_(pattern), what_(std::move(what)) {
    glob_t g;
    std::memset(&g, 0, sizeof g);
    const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);
    std::vector<std::string> files;
    if (rc == 0)
        for (std::size_t i = 0; i < g.gl_pathc; ++i) files.push_back(g.gl_pathv[i]);
    globfree(&g);
    if (files.empty()) fail<InputError>(what_, ": no file matches '", pattern, "'");
    for (const auto& f : files) scan(f);
    if (index_.empty()) fail<InputError>(what_, " '", pattern, "': no frames in ", files.size(), " file(s)");
}

void LiggghtsDumpSeries::scan(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail<InputError>(what_, ": cannot open file '", file, "' (", std::strerror(errno), ")");
    long line = 0;
    std::string s;
    while (true) {
        // Skip blank lines between frames; stop at the end of the file.
        std::streampos pos = in.tellg();
        long startLine = line;
        bool more = false;
        while (std::getline(in, s)) {
            ++line;
            if (!s.empty() && s != "\r") {
                more = true;
                break;
            }
            pos = in.tellg();
            startLine = line;
        }
        if (!more) break;
        if (!startsWith(s, "ITEM: TIMESTEP"))
            fail<InputError>(what_, ": file '", file, "' line ", line, ": expected 'ITEM: TIMESTEP', found '",
                             s.substr(0, 60), "' (not a LIGGGHTS text dump?)");
        in.seekg(pos);
        line = startLine;
        const long frameLine = line + 1;
        const Header h = readHeader(in, file, line);
        for (std::size_t r = 0; r < h.rows; ++r) {
            if (!std::getline(in, s))
                fail<InputError>(what_, ": file '", file, "' (time step ", h.step, ") ends after ", r, " of ",
                                 h.rows, " rows");
            ++line;
        }
        if (index_.count(h.step)) {
            const auto& o = index_.at(h.step);
            if (o.file != file || o.offset != long(pos))
                fail<InputError>(what_, ": time step ", h.step, " is in '", o.file, "' (line ", o.line, ") and in '",
                                 file, "' (line ", frameLine, ")");
        }
        index_[h.step] = Location{file, long(pos), frameLine};
    }
}

std::vector<long> LiggghtsDumpSeries::steps() const {
    std::vector<long> s;
    for (const auto& kv : index_) s.push_back(kv.first);
    return s;
}

DumpFrame LiggghtsDumpSeries::read(long step) const {
    auto it = index_.find(step);
    if (it == index_.end()) fail<InputError>(what_, " '", pattern_, "': no frame for time step ", step);
    const Location& loc = it->second;
    std::ifstream in(loc.file, std::ios::binary);
    if (!in) fail<InputError>(what_, ": cannot open file '", loc.file, "' (", std::strerror(errno), ")");
    in.seekg(loc.offset);
    long line = loc.line - 1;
    const Header h = readHeader(in, loc.file, line);
    DumpFrame f;
    f.file = loc.file;
    f.step = h.step;
    f.domain = h.domain;
    f.columns = h.columns;
    f.rows = h.rows;
    const std::size_t nc = f.columns.size();
    f.data.resize(f.rows * nc);
    std::string s;
    for (std::size_t r = 0; r < f.rows; ++r) {
        std::getline(in, s);
        ++line;
        const char* p = s.c_str();
        for (std::size_t c = 0; c < nc; ++c) {
            char* end = nullptr;
            const double v = std::strtod(p, &end);
            if (end == p)
                fail<InputError>(what_, ": file '", loc.file, "' line ", line, ": expected ", nc,
                                 " numbers (columns ", f.columns.front(), " ... ", f.columns.back(), "), found ", c,
                                 " in '", s.substr(0, 80), "'");
            f.data[r * nc + c] = v;
            p = end;
        }
        while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
        if (*p)
            fail<InputError>(what_, ": file '", loc.file, "' line ", line, ": more than the ", nc,
                             " values the column line names");
    }
    return f;
}

}  // namespace granair
