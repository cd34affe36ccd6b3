#include "yaml/map_reader.h"

#include <algorithm>
#include <unordered_set>

namespace fh {

namespace {

// The end of the message for an unknown key. In a flow map, "{radius:1}"
// (no space after the colon) and "{radius 1}" (no colon) are keys with no
// value; say so rather than suggest the key the name is close to.
std::string unknown_key_hint(const std::string& name, const std::vector<std::string>& allowed) {
    const std::size_t colon = name.find(':');
    if (colon != std::string::npos && colon > 0 && colon + 1 < name.size() && name[colon + 1] != ' ')
        return " (a missing space after the colon? write '" + name.substr(0, colon + 1) + " " +
               name.substr(colon + 1) + "')";
    const std::size_t space = name.find(' ');
    const std::size_t value = space == std::string::npos ? space : name.find_first_not_of(' ', space);
    if (value != std::string::npos && std::find(allowed.begin(), allowed.end(), name.substr(0, space)) != allowed.end())
        return " (a missing colon? write '" + name.substr(0, space) + ": " + name.substr(value) + "')";
    const std::string hint = closest_match(name, allowed);
    return hint.empty() ? "" : " (did you mean '" + hint + "'?)";
}

}  // namespace

MapReader::MapReader(const YamlReader& reader, const YAML::Node& map, std::string what,
                     const std::vector<std::string>& allowed)
    : reader_(reader), map_(map), what_(std::move(what)) {
    reader_.expect_map(map_, what_);
    // Seen keys in a hash set: a map of a hundred thousand names is checked in
    // linear time, not quadratic.
    std::unordered_set<std::string> seen;
    for (auto it = map_.begin(); it != map_.end(); ++it) {
        // A copy: the iterator's `->` hands out a proxy that dies with the statement.
        const YAML::Node key = it->first;
        if (!key.IsScalar()) reader_.fail(key, "expected a name as key in " + what_ + ", " + got(key));
        const std::string& name = key.Scalar();
        // yaml-cpp keeps both copies of a repeated key and lookups see the first:
        // a repeated key is almost surely a mistake.
        if (!seen.insert(name).second) reader_.fail(key, "duplicate key '" + name + "' in " + what_);
        if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            reader_.fail(key, "unknown key '" + name + "' in " + what_ + unknown_key_hint(name, allowed));
        entries_.push_back({key.Scalar(), key, it->second});
    }
}

const MapReader::Entry* MapReader::find(const std::string& key) const {
    for (const Entry& e : entries_)
        if (e.key == key) return &e;
    return nullptr;
}

const MapReader::Entry& MapReader::required(const std::string& key) const {
    const Entry* e = find(key);
    if (!e) reader_.fail(map_, "missing key '" + key + "' in " + what_);
    return *e;
}

YAML::Node MapReader::value(const std::string& key) const {
    const Entry& e = required(key);
    if (e.value.IsNull()) reader_.fail(e.key_node, "missing value for '" + key + "'");
    return e.value;
}

double MapReader::number(const std::string& key) const { return reader_.number(value(key), key); }

double MapReader::number_or(const std::string& key, double fallback) const {
    return has(key) ? number(key) : fallback;
}

double MapReader::number_at_least(const std::string& key, double min) const {
    return reader_.number_at_least(value(key), key, min);
}

double MapReader::positive(const std::string& key) const { return reader_.positive(value(key), key); }
double MapReader::number_up_to(const std::string& key, double min, double max) const {
    return reader_.number_up_to(value(key), key, min, max);
}
double MapReader::positive_up_to(const std::string& key, double max) const {
    return reader_.positive_up_to(value(key), key, max);
}

int MapReader::integer(const std::string& key, int min, int max) const {
    return reader_.integer(value(key), key, min, max);
}

bool MapReader::boolean_or(const std::string& key, bool fallback) const {
    return has(key) ? reader_.boolean(value(key), key) : fallback;
}

std::string MapReader::string(const std::string& key) const { return reader_.string(value(key), key); }
dvec3 MapReader::vec3(const std::string& key) const { return reader_.vec3(value(key), key); }
dvec3 MapReader::color(const std::string& key) const { return reader_.color(value(key), key); }
dvec3 MapReader::direction(const std::string& key) const { return reader_.direction(value(key), key); }

}  // namespace fh
