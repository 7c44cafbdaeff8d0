// Dictionary.cpp: tokenizer and recursive reader for the OpenFOAM-like subset.
#include "core/Dictionary.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"

namespace granair {

Dictionary::Dictionary(std::string source, std::string path)
    : source_(std::move(source)), path_(std::move(path)) {}

// ---------------------------------------------------------------------------
class DictionaryParser {
public:
    DictionaryParser(const std::string& text, const std::string& source)
        : text_(text), source_(source) {}

    void parseInto(Dictionary& d, bool topLevel) {
        for (;;) {
            std::string key = next();
            if (key.empty()) {
                if (!topLevel) error("unexpected end of file inside '", d.path_, "' (missing '}')");
                return;
            }
            if (key == "}") {
                if (topLevel) error("unmatched '}'");
                return;
            }
            if (key == "{" || key == ";") error("expected a keyword, found '", key, "'");
            if (key == "(" || key == ")") error("expected a keyword, found '", key, "' (a list without a keyword?)");
            const int keyLine = line_;
            if (d.line_.count(key))
                error("key '", d.path_.empty() ? key : d.path_ + "." + key, "' given twice (first on line ",
                      d.line_.at(key), ")");
            d.line_[key] = keyLine;
            std::string tok = next();
            if (tok == "{") {
                auto sub = std::make_shared<Dictionary>(
                    d.source_, d.path_.empty() ? key : d.path_ + "." + key);
                parseInto(*sub, false);
                d.order_.push_back(key);
                d.endLine_[key] = line_;
                d.dicts_[key] = sub;
                continue;
            }
            std::vector<std::string> value;
            int depth = 0;
            while (tok != ";" || depth > 0) {
                if (tok.empty()) error("entry '", key, "' (line ", keyLine, ") is not closed by ';'");
                if (tok == "(") ++depth;
                if (tok == ")") --depth;
                if (tok == "{" || tok == "}")
                    error("entry '", key, "' (line ", keyLine, "): unexpected '", tok, "' before ';'",
                          line_ > keyLine ? " (is a ';' missing at the end of line " + std::to_string(keyLine) + "?)"
                                          : std::string());
                value.push_back(tok);
                tok = next();
            }
            d.order_.push_back(key);
            d.endLine_[key] = line_;
            d.entries_[key] = std::move(value);
        }
    }

private:
    const std::string& text_;
    const std::string& source_;
    size_t pos_ = 0;
    int line_ = 1;

    template <class... P>
    [[noreturn]] void error(const P&... p) {
        fail<InputError>("file '", source_, "' line ", line_, ": ", p...);
    }

    void skipSpaceAndComments() {
        while (pos_ < text_.size()) {
            char c = text_[pos_];
            if (c == '\n') { ++line_; ++pos_; }
            else if (std::isspace(static_cast<unsigned char>(c))) ++pos_;
            else if (text_.compare(pos_, 2, "//") == 0) {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            } else if (text_.compare(pos_, 2, "/*") == 0) {
                size_t end = text_.find("*/", pos_ + 2);
                if (end == std::string::npos) error("unterminated /* comment");
                for (size_t i = pos_; i < end; ++i) line_ += text_[i] == '\n';
                pos_ = end + 2;
            } else return;
        }
    }

    std::string next() {
        skipSpaceAndComments();
        if (pos_ >= text_.size()) return "";
        char c = text_[pos_];
        if (c == '{' || c == '}' || c == ';' || c == '(' || c == ')') {
            ++pos_;
            return std::string(1, c);
        }
        if (c == '"') {
            size_t end = text_.find('"', pos_ + 1);
            if (end == std::string::npos) error("unterminated string");
            std::string s = text_.substr(pos_ + 1, end - pos_ - 1);
            pos_ = end + 1;
            return s;
        }
        size_t start = pos_;
        while (pos_ < text_.size()) {
            char d = text_[pos_];
            if (std::isspace(static_cast<unsigned char>(d)) || d == '{' || d == '}' || d == ';' ||
                d == '(' || d == ')' || text_.compare(pos_, 2, "//") == 0 ||
                text_.compare(pos_, 2, "/*") == 0)
                break;
            ++pos_;
        }
        return text_.substr(start, pos_ - start);
    }
};

Dictionary Dictionary::fromString(const std::string& text, const std::string& source) {
    Dictionary d(source);
    DictionaryParser(text, source).parseInto(d, true);
    d.allow({"FoamFile"});  // OpenFOAM's header: nobody reads it
    return d;
}

Dictionary Dictionary::fromFile(const std::string& fileName) {
    std::ifstream in(fileName);
    if (!in) fail<InputError>("cannot open file '", fileName, "'");
    std::stringstream ss;
    ss << in.rdbuf();
    return fromString(ss.str(), fileName);
}

// ---------------------------------------------------------------------------
std::string Dictionary::where(const std::string& key) const {
    return "file '" + source_ + "', key '" + (path_.empty() ? key : path_ + "." + key) + "'";
}

bool Dictionary::has(const std::string& key) const {
    markKnown(key);
    return entries_.count(key) || dicts_.count(key);
}
bool Dictionary::isDict(const std::string& key) const {
    markKnown(key);
    return dicts_.count(key) > 0;
}

std::vector<std::string> Dictionary::keys() const {
    allKnown_ = true;
    return order_;
}

void Dictionary::allow(std::initializer_list<const char*> keys) const {
    for (const char* k : keys) markKnown(k);
}

int Dictionary::line(const std::string& key) const {
    auto it = line_.find(key);
    return it == line_.end() ? 0 : it->second;
}

namespace {

// Edit distance, case-insensitive: how far a misspelled key is from a known one.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

}  // namespace

void Dictionary::checkKnownKeys() const {
    for (const std::string& key : order_) {
        if (!allKnown_ && !known_.count(key)) {
            // Suggest among the keys this dictionary's readers asked for
            // (present or not); FoamFile is no suggestion.
            std::string closest, list;
            std::size_t best = std::string::npos;
            for (const std::string& k : known_) {
                if (k == "FoamFile") continue;
                list += (list.empty() ? "" : ", ") + k;
                const std::size_t dist = editDistance(key, k);
                if (dist < best) {
                    best = dist;
                    closest = k;
                }
            }
            fail<InputError>("file '", source_, "' line ", line(key), ": unknown key '",
                             path_.empty() ? key : path_ + "." + key, "'",
                             closest.empty() ? std::string(" (no keys are read here)")
                                             : " (did you mean '" + closest + "'? known here: " + list + ")");
        }
        auto sub = dicts_.find(key);
        // A sub-dictionary nobody looked into is not checked (it was allowed
        // whole, or its reader iterates it: keys()).
        if (sub != dicts_.end() && (!sub->second->known_.empty() || sub->second->allKnown_))
            sub->second->checkKnownKeys();
    }
}

const Dictionary& Dictionary::subDict(const std::string& key) const {
    markKnown(key);
    auto it = dicts_.find(key);
    if (it == dicts_.end())
        fail<InputError>(where(key), ": missing sub-dictionary (expected '", key, " { ... }')");
    return *it->second;
}

const std::vector<std::string>& Dictionary::tokens(const std::string& key) const {
    markKnown(key);
    auto it = entries_.find(key);
    if (it == entries_.end()) {
        if (dicts_.count(key)) fail<InputError>(where(key), ": expected a value, found a sub-dictionary");
        fail<InputError>(where(key), ": missing keyword");
    }
    return it->second;
}

void Dictionary::badValue(const std::string& key, const std::string& what) const {
    const auto& t = entries_.at(key);
    std::string found;
    for (const std::string& w : t) found += (found.empty() ? "" : " ") + w;
    const int first = line(key), last = endLine_.count(key) ? endLine_.at(key) : first;
    std::string hint;
    if (t.size() > 1 && last > first)
        hint = " (is a ';' missing at the end of line " + std::to_string(first) + "?)";
    fail<InputError>(where(key), first > 0 ? " (line " + std::to_string(first) + ")" : std::string(),
                     ": expected ", what, ", found '", found, "'", hint);
}

std::string Dictionary::getString(const std::string& key) const {
    const auto& t = tokens(key);
    if (t.size() != 1) badValue(key, "a single word");
    return t[0];
}
std::string Dictionary::getString(const std::string& key, const std::string& fallback) const {
    return has(key) ? getString(key) : fallback;
}

static bool parseDouble(const std::string& s, double& v) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && errno != ERANGE;
}

double Dictionary::getDouble(const std::string& key) const {
    const auto& t = tokens(key);
    double v;
    if (t.size() != 1 || !parseDouble(t[0], v)) badValue(key, "a number");
    if (!std::isfinite(v)) fail<InputError>(where(key), ": expected a finite number, found '", t[0], "'");
    return v;
}
double Dictionary::getDouble(const std::string& key, double fallback) const {
    return has(key) ? getDouble(key) : fallback;
}
double Dictionary::getDouble(const std::string& key, double lo, double hi) const {
    double v = getDouble(key);
    if (v < lo || v > hi)
        fail<InputError>(where(key), ": value ", v, " out of range, expected ", lo, " <= ", key, " <= ", hi);
    return v;
}

long Dictionary::getInt(const std::string& key) const {
    const auto& t = tokens(key);
    char* end = nullptr;
    long v = t.size() == 1 ? std::strtol(t[0].c_str(), &end, 10) : 0;
    if (t.size() != 1 || end != t[0].c_str() + t[0].size() || t[0].empty()) badValue(key, "an integer");
    return v;
}
long Dictionary::getInt(const std::string& key, long fallback) const {
    return has(key) ? getInt(key) : fallback;
}

bool Dictionary::getBool(const std::string& key, bool fallback) const {
    if (!has(key)) return fallback;
    std::string s = getString(key);
    if (s == "true" || s == "yes" || s == "on" || s == "1") return true;
    if (s == "false" || s == "no" || s == "off" || s == "0") return false;
    fail<InputError>(where(key), ": expected true/false (or yes/no, on/off), found '", s, "'");
}

Vec3 Dictionary::getVec3(const std::string& key) const {
    const auto& t = tokens(key);
    Vec3 v;
    if (t.size() != 5 || t[0] != "(" || t[4] != ")" || !parseDouble(t[1], v.x()) ||
        !parseDouble(t[2], v.y()) || !parseDouble(t[3], v.z()))
        badValue(key, "a vector '(x y z)'");
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(v[a]))
            fail<InputError>(where(key), line(key) > 0 ? " (line " + std::to_string(line(key)) + ")" : std::string(),
                             ": component ", "xyz"[a], " of the vector is '", t[1 + a],
                             "', expected finite numbers '(x y z)'");
    return v;
}
Vec3 Dictionary::getVec3(const std::string& key, const Vec3& fallback) const {
    return has(key) ? getVec3(key) : fallback;
}

void Dictionary::set(const std::string& key, const std::string& value) {
    Dictionary parsed = fromString(key + " " + value + ";", source_);
    if (!entries_.count(key) && !dicts_.count(key)) order_.push_back(key);
    dicts_.erase(key);
    entries_[key] = parsed.entries_.at(key);
}

Dictionary& Dictionary::addDict(const std::string& key) {
    if (!entries_.count(key) && !dicts_.count(key)) order_.push_back(key);
    entries_.erase(key);
    auto& p = dicts_[key];
    if (!p) p = std::make_shared<Dictionary>(source_, path_.empty() ? key : path_ + "." + key);
    return *p;
}

}  // namespace granair
