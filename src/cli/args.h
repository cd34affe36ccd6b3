// A small, strict command-line parser: each command names the flags it takes;
// anything else is a usage error (with a suggestion for a near miss).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/closest_match.h"
#include "io/parse_int.h"

namespace fh {

struct FlagSpec {
    std::string name;  // with dashes: "--spp", "-o"
    bool takes_value = true;
};

class Args {
public:
    static Args parse(const std::string& command, const std::vector<std::string>& words,
                      const std::vector<FlagSpec>& spec);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& flag) const { return values_.count(flag) > 0; }
    std::optional<std::string> value(const std::string& flag) const;
    // An integer flag in [min, max]; absent: fallback.
    int integer(const std::string& flag, int fallback, int min, int max) const;

private:
    std::string command_;
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
};



}  // namespace fh
