// Dictionary.cpp: tokenizer and recursive reader for the OpenFOAM-like subset.
#include "core/Dictionary.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
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
            std::string tok = next();
            if (tok == "{") {
                auto sub = std::make_shared<Dictionary>(
                    d.source_, d.path_.empty() ? key : d.path_ + "." + key);
                parseInto(*sub, false);
                if (!d.dicts_.count(key) && !d.entries_.count(key)) d.order_.push_back(key);
                d.entries_.erase(key);
                d.dicts_[key] = sub;
                continue;
            }
            std::vector<std::string> value;
            int depth = 0;
            while (tok != ";" || depth > 0) {
                if (tok.empty()) error("entry '", key, "' is not closed by ';'");
                if (tok == "(") ++depth;
                if (tok == ")") --depth;
                if (tok == "{" || tok == "}") error("entry '", key, "': unexpected '", tok, "' before ';'");
                value.push_back(tok);
                tok = next();
            }
            if (!d.dicts_.count(key) && !d.entries_.count(key)) d.order_.push_back(key);
            d.dicts_.erase(key);
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
    return entries_.count(key) || dicts_.count(key);
}
bool Dictionary::isDict(const std::string& key) const { return dicts_.count(key) > 0; }

std::vector<std::string> Dictionary::keys() const { return order_; }

const Dictionary& Dictionary::subDict(const std::string& key) const {
    auto it = dicts_.find(key);
    if (it == dicts_.end())
        fail<InputError>(where(key), ": missing sub-dictionary (expected '", key, " { ... }')");
    return *it->second;
}

const std::vector<std::string>& Dictionary::tokens(const std::string& key) const {
    auto it = entries_.find(key);
    if (it == entries_.end()) {
        if (dicts_.count(key)) fail<InputError>(where(key), ": expected a value, found a sub-dictionary");
        fail<InputError>(where(key), ": missing keyword");
    }
    return it->second;
}

std::string Dictionary::getString(const std::string& key) const {
    const auto& t = tokens(key);
    if (t.size() != 1) fail<InputError>(where(key), ": expected a single word");
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
    if (t.size() != 1 || !parseDouble(t[0], v))
        fail<InputError>(where(key), ": expected a number, found '", t.empty() ? "" : t[0], "'");
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
    if (t.size() != 1 || end != t[0].c_str() + t[0].size() || t[0].empty())
        fail<InputError>(where(key), ": expected an integer, found '", t.empty() ? "" : t[0], "'");
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
        !parseDouble(t[2], v.y()) || !parseDouble(t[3], v.z()) || !v.allFinite())
        fail<InputError>(where(key), ": expected a vector '(x y z)'");
    return v;
}
Vec3 Dictionary::getVec3(const std::string& key, const Vec3& fallback) const {
    return has(key) ? getVec3(key) : fallback;
}

void Dictionary::set(const std::string& key, const std::string& value) {
    Dictionary parsed = fromString(key + " " + value + ";", source_);
    if (!has(key)) order_.push_back(key);
    dicts_.erase(key);
    entries_[key] = parsed.entries_.at(key);
}

Dictionary& Dictionary::addDict(const std::string& key) {
    if (!has(key)) order_.push_back(key);
    entries_.erase(key);
    auto& p = dicts_[key];
    if (!p) p = std::make_shared<Dictionary>(source_, path_.empty() ? key : path_ + "." + key);
    return *p;
}

}  // namespace granair
