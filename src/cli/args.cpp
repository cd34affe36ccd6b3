#include "cli/args.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "text/input_error.h"

namespace fh {

namespace {

[[noreturn]] void unknown_flag(const CommandSpec& command, const std::string& name) {
    const std::string cmd(command.name);
    for (const Pointer& p : command.pointers)
        if (p.flag == name) throw UsageError("'" + cmd + "' has no option '" + name + "': " + std::string(p.advice));
    std::vector<std::string> names;
    for (std::string_view f : command.flags) {
        names.emplace_back(f);
        if (!find_flag(f).alias.empty()) names.emplace_back(find_flag(f).alias);
    }
    const std::string near = closest_match(name, names);
    throw UsageError("unknown option '" + name + "' for '" + cmd + "'" +
                     (near.empty() ? "" : " (did you mean '" + near + "'?)") + "; see 'firsthit " + cmd +
                     " --help'");
}

}  // namespace

Args Args::parse(const CommandSpec& command, const std::vector<std::string>& words) {
    Args args;
    for (size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w.size() < 2 || w[0] != '-') {  // a file, or '-'
            args.positional_.push_back(w);
            continue;
        }
        std::string name = w, inline_value;
        const bool has_inline = w.rfind("--", 0) == 0 && w.find('=') != std::string::npos;
        if (has_inline) {
            name = w.substr(0, w.find('='));
            inline_value = w.substr(w.find('=') + 1);
        }
        const auto it = std::find_if(command.flags.begin(), command.flags.end(), [&](std::string_view f) {
            return f == name || find_flag(f).alias == name;
        });
        if (it == command.flags.end()) unknown_flag(command, name);
        const Flag& flag = find_flag(*it);
        const std::string key(flag.name);
        if (flag.value.empty()) {
            if (has_inline) throw UsageError("option '" + name + "' takes no value");
            args.values_[key] = "";
        } else if (has_inline) {
            args.values_[key] = inline_value;
        } else {
            if (i + 1 >= words.size())
                throw UsageError("option '" + name + "' needs a value (" + std::string(flag.value) + ")");
            args.values_[key] = words[++i];
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

double Args::number(const std::string& flag, double fallback, double min, double max) const {
    const auto v = value(flag);
    if (!v) return fallback;
    char* end = nullptr;
    const double x = std::strtod(v->c_str(), &end);
    if (v->empty() || *end != '\0' || !std::isfinite(x) || x < min || x > max) {
        std::ostringstream range;
        range << "[" << min << ", " << max << "]";
        throw UsageError(flag + " must be a number in " + range.str() + ", got '" + *v + "'");
    }
    return x;
}

}  // namespace fh
