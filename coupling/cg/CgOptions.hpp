// CgOptions.hpp: granairCG's settings from its command line and/or a dictionary.
//
// Every option has a dictionary key of the same meaning (camelCase of the
// long option: --time-average <-> timeAverage); options on the command line
// override the dictionary (--dict FILE). Errors name where a value came
// from: "command line option --width" or "file 'cg.dict', key 'width'".
// The option list and its help text live in one table (CgOptions.cpp).
#pragma once
#include <map>
#include <string>
#include <vector>

namespace granair {

class CgOptions {
public:
    // argv without the program name; reads --dict first if given.
    static CgOptions fromArgs(const std::vector<std::string>& args);
    static std::string help();  // the option list with one line each

    bool has(const std::string& key) const { return values_.count(key) > 0; }
    bool flag(const std::string& key) const;
    std::string getString(const std::string& key, const std::string& fallback) const;
    std::string getString(const std::string& key) const;
    double getDouble(const std::string& key, double fallback) const;
    double getDouble(const std::string& key) const;
    long getInt(const std::string& key, long fallback) const;
    // A list of numbers with between lo and hi entries.
    std::vector<double> getNumbers(const std::string& key, std::size_t lo, std::size_t hi) const;
    // Raw words (for repeated options: all occurrences, concatenated).
    const std::vector<std::string>& words(const std::string& key) const;
    // "command line option --width" or "file 'x', key 'width'".
    std::string where(const std::string& key) const;
    bool wantsHelp() const { return help_; }

private:
    struct Value {
        std::vector<std::string> words;
        std::string where;
    };
    std::map<std::string, Value> values_;
    bool help_ = false;
};

}  // namespace granair
