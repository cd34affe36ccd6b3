// A small, strict command-line parser: a command takes exactly the flags its
// entry in the command table lists (cli/flags.h); anything else is a usage
// error, with a pointer to the right flag or command, or a near miss.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/flags.h"
#include "text/closest_match.h"
#include "text/parse_int.h"

namespace fh {

class Args {
public:
    // words: what follows the command's name. Values are stored under the
    // flag's name, also when its alias was typed (-o OUT: "--output").
    static Args parse(const CommandSpec& command, const std::vector<std::string>& words);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& flag) const { return values_.count(flag) > 0; }
    std::optional<std::string> value(const std::string& flag) const;
    // An integer flag in [min, max]; absent: fallback.
    int integer(const std::string& flag, int fallback, int min, int max) const;
    // A number flag in [min, max]; absent: fallback.
    double number(const std::string& flag, double fallback, double min, double max) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
};

}  // namespace fh
