// Dictionary.hpp: read the coupling settings of a case.
//
// The case files are OpenFOAM dictionaries (constant/couplingProperties), but
// coupling/ must not depend on OpenFOAM, so this is a small reader for the
// subset we use:  `key value ... ;`  and  `name { ... }`, with // and /* */
// comments; the FoamFile header block is read like any other sub-dictionary.
// Every getter that fails names the file, the full key path and what was
// expected, so bad input never surfaces as a bare exception.
//
// Strict: a key given twice in one dictionary is an error (with both lines);
// syntax errors name the line. Unknown keys: every lookup (has, subDict,
// get*) records the key it asked for as known, so the readers declare their
// keys simply by reading them (defaults included: get(key, fallback) asks
// too); keys() marks every key known (a reader of user-named entries);
// allow() declares keys a reader deliberately ignores. Once every reader has
// read, checkKnownKeys() throws InputError for the first key nobody asked
// for, naming the file, its line, the key and the closest known key.
#pragma once
#include <initializer_list>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Vec3.hpp"

namespace granair {

class Dictionary {
public:
    Dictionary() = default;
    // source: a file name (or description) used in every error message.
    explicit Dictionary(std::string source, std::string path = "");

    static Dictionary fromFile(const std::string& fileName);
    static Dictionary fromString(const std::string& text, const std::string& source);

    bool has(const std::string& key) const;
    bool isDict(const std::string& key) const;
    const Dictionary& subDict(const std::string& key) const;
    // Every key in file order; marks them all known.
    std::vector<std::string> keys() const;

    // Keys a reader accepts without reading them (e.g. `monitors` of a
    // DEM-only run: nothing in them is used, nothing in them is checked).
    void allow(std::initializer_list<const char*> keys) const;
    // Throws InputError for the first key of this dictionary or of a
    // sub-dictionary that some reader looked into, that no reader asked for:
    // "file 'F' line L: unknown key 'drag.swichVoidFraction' (did you mean
    // 'switchVoidFraction'? known here: switchVoidFraction, type)".
    void checkKnownKeys() const;
    // Line of a key in its file (0 if set programmatically or missing).
    int line(const std::string& key) const;

    // Raw tokens of an entry, e.g. {"(", "0", "0", "-9.81", ")"}.
    const std::vector<std::string>& tokens(const std::string& key) const;

    std::string getString(const std::string& key) const;
    std::string getString(const std::string& key, const std::string& fallback) const;
    double getDouble(const std::string& key) const;
    double getDouble(const std::string& key, double fallback) const;
    // Range-checked: lo <= value <= hi, with the range in the error message.
    double getDouble(const std::string& key, double lo, double hi) const;
    long getInt(const std::string& key) const;
    long getInt(const std::string& key, long fallback) const;
    bool getBool(const std::string& key, bool fallback) const;
    Vec3 getVec3(const std::string& key) const;
    Vec3 getVec3(const std::string& key, const Vec3& fallback) const;

    // Programmatic construction (tests, defaults).
    void set(const std::string& key, const std::string& value);
    Dictionary& addDict(const std::string& key);

    const std::string& source() const { return source_; }
    // Where a key lives, for messages: "file 'x', key 'drag.type'".
    std::string where(const std::string& key) const;

private:
    std::string source_;
    std::string path_;  // dotted path of this sub-dictionary, "" at top level
    std::map<std::string, std::vector<std::string>> entries_;
    std::map<std::string, std::shared_ptr<Dictionary>> dicts_;
    std::vector<std::string> order_;
    std::map<std::string, int> line_, endLine_;  // line of the key, of its ';'
    mutable std::set<std::string> known_;  // keys some reader asked for
    mutable bool allKnown_ = false;        // keys() was called

    void markKnown(const std::string& key) const { known_.insert(key); }
    // "expected <what>, found '...'" with the line, and a hint at a missing
    // ';' when the value runs over several lines.
    [[noreturn]] void badValue(const std::string& key, const std::string& what) const;

    friend class DictionaryParser;
};

}  // namespace granair
