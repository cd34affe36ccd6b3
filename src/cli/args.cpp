#include "cli/args.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "io/input_error.h"

namespace fh {

Args Args::parse(const std::string& command, const std::vector<std::string>& words,
                 const std::vector<FlagSpec>& spec) {
    Args args;
    args.command_ = command;
    for (size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w.size() < 2 || w[0] != '-') {
            args.positional_.push_back(w);
            continue;
        }
        std::string name = w, inline_value;
        const bool has_inline = w.rfind("--", 0) == 0 && w.find('=') != std::string::npos;
        if (has_inline) {
            name = w.substr(0, w.find('='));
            inline_value = w.substr(w.find('=') + 1);
        }
        const auto it = std::find_if(spec.begin(), spec.end(),
                                     [&](const FlagSpec& f) { return f.name == name; });
        if (it == spec.end()) {
            std::vector<std::string> names;
            for (const auto& f : spec) names.push_back(f.name);
            const std::string near = closest_match(name, names);
            throw UsageError("unknown option '" + name + "' for '" + command + "'" +
                             (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                             "; see 'firsthit " + command + " --help'");
        }
        if (!it->takes_value) {
            if (has_inline) throw UsageError("option '" + name + "' takes no value");
            args.values_[name] = "";
        } else if (has_inline) {
            args.values_[name] = inline_value;
        } else {
            if (i + 1 >= words.size()) throw UsageError("option '" + name + "' needs a value");
            args.values_[name] = words[++i];
        }
    }
    return args;
}

std::optional<std::string> Args::value(const std::string& flag) const {
    const auto it = values_.find(flag);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

int Args::integer(const std::string& flag, int fallback, int min, int max) const {
    const auto v = value(flag);
    return v ? parse_int(*v, flag, min, max) : fallback;
}

}  // namespace fh
