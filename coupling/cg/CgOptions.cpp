// CgOptions.cpp: see CgOptions.hpp.
#include "cg/CgOptions.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

namespace granair {

namespace {

struct Spec {
    const char* option;  // without the leading --
    const char* key;     // dictionary key
    int minWords, maxWords;
    bool repeat;
    const char* help;
};

// The options of granairCG (docs/cg-fields.md, "Command line").
const Spec specs[] = {
    {"dict", "", 1, 1, false, "FILE   read the settings from a dictionary (keys: camelCase of the options)"},
    {"particles", "particles", 1, 1, false, "GLOB   particle dumps (dump custom: id x y z vx vy vz radius mass [omegax omegay omegaz])"},
    {"pairs", "pairs", 1, 1, false, "GLOB   pair-contact dumps (compute pair/gran/local + dump local)"},
    {"walls", "walls", 1, 1, false, "GLOB   mesh-wall contact dumps (compute wall/gran/local + dump local)"},
    {"pair-layout", "pairLayout", 1, 15, false, "KEYS   keywords of the pair compute (default: pos id force)"},
    {"wall-layout", "wallLayout", 1, 15, false, "KEYS   keywords of the wall compute (default: pos id force)"},
    {"plane-wall", "planeWalls", 3, 3, true, "FIX AXIS POS  a primitive plane wall with store_force yes (repeatable)"},
    {"dt", "dt", 1, 1, false, "S      the DEM time step: times in s (default: times are step numbers)"},
    {"coordinates", "coordinates", 1, 1, false, "C      XYZ XY XZ YZ X Y Z RZ or O (default XYZ)"},
    {"kernel", "kernel", 1, 1, false, "NAME   gauss (default), heaviside or lucy"},
    {"width", "width", 1, 1, false, "W      kernel width [m]: gauss w, heaviside/lucy cutoff radius"},
    {"cutoff", "cutoff", 1, 1, false, "K      gauss cutoff in widths (default 3)"},
    {"std", "std", 1, 1, false, "S      kernel standard deviation per axis [m], instead of --width"},
    {"n", "n", 1, 3, false, "N..    grid points along each resolved axis (one number: all)"},
    {"spacing", "spacing", 1, 1, false, "H      grid spacing [m] instead of --n (default: the kernel's standard deviation)"},
    {"min", "min", 3, 3, false, "X Y Z  window lower corner [m] (default: the dump's box)"},
    {"max", "max", 3, 3, false, "X Y Z  window upper corner [m]"},
    {"axis", "axis", 2, 2, false, "X0 Y0  RZ: the axis position (default: the box centre)"},
    {"rmin", "rmin", 1, 1, false, "R      RZ: smallest radius (default 0)"},
    {"rmax", "rmax", 1, 1, false, "R      RZ: largest radius (default: the largest circle in the box)"},
    {"time-average", "timeAverage", 1, 1, false, "KIND   uniform (default) or gauss"},
    {"from", "from", 1, 1, false, "T      uniform average: first time"},
    {"to", "to", 1, 1, false, "T      uniform average: last time"},
    {"centre", "centre", 1, 1, false, "T      gauss average: centre time"},
    {"time-width", "timeWidth", 1, 1, false, "S      gauss average: standard deviation in time (cut at 3)"},
    {"every", "every", 0, 0, false, "       also write every snapshot (stem_<step>.*, stem.pvd)"},
    {"out", "out", 1, 1, false, "STEM   output path without extension (default: cg)"},
    {"format", "format", 1, 3, false, "F..    any of vti h5 csv (default: all three)"},
    {"threads", "threads", 1, 1, false, "N      OpenMP threads (default: OMP_NUM_THREADS or all cores)"},
    {"min-volume-fraction", "minVolumeFraction", 1, 1, false, "F      velocity etc. are NaN below it (default 1e-3)"},
    {"azimuthal-nodes", "azimuthalNodes", 1, 1, false, "N      RZ: Gauss nodes in the angle (default 16)"},
    {"help", "", 0, 0, false, "       this list"},
};

const Spec* findOption(const std::string& name) {
    for (const auto& s : specs)
        if (name == s.option) return &s;
    return nullptr;
}

const Spec* findKey(const std::string& key) {
    for (const auto& s : specs)
        if (key == s.key && *s.key) return &s;
    return nullptr;
}

bool isOption(const std::string& w) {
    if (w.size() < 3 || w.compare(0, 2, "--") != 0) return false;
    // a negative number is a value, not an option
    return !(std::isdigit(static_cast<unsigned char>(w[2])) || w[2] == '.');
}

double toDouble(const std::string& w, const std::string& where) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(w.c_str(), &end);
    if (errno || end == w.c_str() || *end || !std::isfinite(v))
        fail<InputError>(where, ": expected a finite number, found '", w, "'");
    return v;
}

}  // namespace

std::string CgOptions::help() {
    std::ostringstream os;
    for (const auto& s : specs) {
        std::string opt = std::string("--") + s.option;
        os << "  " << opt;
        for (std::size_t k = opt.size(); k < 22; ++k) os << ' ';
        os << s.help << "\n";
    }
    return os.str();
}

CgOptions CgOptions::fromArgs(const std::vector<std::string>& args) {
    CgOptions o;
    // Split the command line into options and their words.
    std::vector<std::pair<const Spec*, std::vector<std::string>>> given;
    for (std::size_t i = 0; i < args.size();) {
        const std::string& w = args[i];
        if (!isOption(w))
            fail<InputError>("command line: '", w, "' is not an option (options start with --; try --help)");
        const Spec* s = findOption(w.substr(2));
        if (!s) fail<InputError>("command line: unknown option '", w, "' (try --help)");
        std::vector<std::string> vals;
        ++i;
        while (i < args.size() && !isOption(args[i]) && int(vals.size()) < s->maxWords) vals.push_back(args[i++]);
        if (int(vals.size()) < s->minWords)
            fail<InputError>("command line option --", s->option, ": expected ", s->minWords,
                             s->minWords == s->maxWords ? "" : " or more", " value(s), found ", vals.size());
        given.emplace_back(s, vals);
    }
    for (const auto& g : given)
        if (std::string(g.first->option) == "help") o.help_ = true;
    // The dictionary first, then the command line over it.
    for (const auto& g : given) {
        if (std::string(g.first->option) != "dict") continue;
        const Dictionary d = Dictionary::fromFile(g.second.front());
        for (const auto& key : d.keys()) {
            if (key == "FoamFile") continue;  // an OpenFOAM-style header
            const Spec* s = findKey(key);
            if (!s || d.isDict(key)) {
                std::string list;
                for (const auto& sp : specs)
                    if (*sp.key) list += std::string(" ") + sp.key;
                fail<InputError>(d.where(key), ": unknown setting. Known settings:", list);
            }
            std::vector<std::string> words;
            for (const auto& t : d.tokens(key))
                if (t != "(" && t != ")") words.push_back(t);
            if (int(words.size()) < s->minWords || (!s->repeat && int(words.size()) > s->maxWords) ||
                (s->repeat && words.size() % s->maxWords != 0))
                fail<InputError>(d.where(key), ": expected ", s->minWords,
                                 s->minWords == s->maxWords ? "" : " or more", " value(s), found ", words.size());
            o.values_[key] = Value{words, d.where(key)};
        }
    }
    for (const auto& g : given) {
        const Spec* s = g.first;
        if (!*s->key) continue;
        auto& v = o.values_[s->key];
        const std::string where = std::string("command line option --") + s->option;
        if (s->repeat && v.where == where) v.words.insert(v.words.end(), g.second.begin(), g.second.end());
        else v = Value{g.second, where};
    }
    return o;
}

bool CgOptions::flag(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end()) return false;
    if (it->second.words.empty()) return true;
    const std::string& w = it->second.words.front();
    if (w == "yes" || w == "true" || w == "on") return true;
    if (w == "no" || w == "false" || w == "off") return false;
    fail<InputError>(it->second.where, ": expected yes or no, found '", w, "'");
}

const std::vector<std::string>& CgOptions::words(const std::string& key) const {
    static const std::vector<std::string> none;
    auto it = values_.find(key);
    return it == values_.end() ? none : it->second.words;
}

std::string CgOptions::where(const std::string& key) const {
    auto it = values_.find(key);
    if (it != values_.end()) return it->second.where;
    const Spec* s = findKey(key);
    return s ? std::string("option --") + s->option : "setting '" + key + "'";
}

std::string CgOptions::getString(const std::string& key) const {
    if (!has(key)) fail<InputError>(where(key), ": missing (required)");
    std::string s;
    for (const auto& w : words(key)) s += (s.empty() ? "" : " ") + w;
    return s;
}

std::string CgOptions::getString(const std::string& key, const std::string& fallback) const {
    return has(key) ? getString(key) : fallback;
}

double CgOptions::getDouble(const std::string& key) const {
    if (!has(key)) fail<InputError>(where(key), ": missing (required)");
    const auto& w = words(key);
    if (w.size() != 1) fail<InputError>(where(key), ": expected one number");
    return toDouble(w.front(), where(key));
}

double CgOptions::getDouble(const std::string& key, double fallback) const {
    return has(key) ? getDouble(key) : fallback;
}

long CgOptions::getInt(const std::string& key, long fallback) const {
    if (!has(key)) return fallback;
    const double v = getDouble(key);
    if (v != std::floor(v) || std::abs(v) > 1e15) fail<InputError>(where(key), ": expected an integer, found ", v);
    return long(v);
}

std::vector<double> CgOptions::getNumbers(const std::string& key, std::size_t lo, std::size_t hi) const {
    const auto& w = words(key);
    if (w.size() < lo || w.size() > hi)
        fail<InputError>(where(key), ": expected ", lo, lo == hi ? "" : " to ", lo == hi ? std::string() : std::to_string(hi),
                         " number(s), found ", w.size());
    std::vector<double> v;
    for (const auto& x : w) v.push_back(toDouble(x, where(key)));
    return v;
}

}  // namespace granair
