// Strict reading of one YAML map (see yaml_reader.h): its keys checked against
// the allowed ones, and typed lookups that report the key's or value's position.
#pragma once

#include <string>
#include <vector>

#include "yaml/yaml_reader.h"

namespace fh {

// A map whose keys are checked once, on construction, against the keys it may
// have: unknown key (with a "did you mean" hint), duplicate key or non-scalar
// key is an error at that key. `what` names the map in messages ("sphere").
// An empty `allowed` accepts any key (maps from names to things).
class MapReader {
public:
    MapReader(const YamlReader& reader, const YAML::Node& map, std::string what,
              const std::vector<std::string>& allowed);

    struct Entry {
        std::string key;
        YAML::Node key_node;
        YAML::Node value;
    };
    const std::vector<Entry>& entries() const { return entries_; }
    const YAML::Node& node() const { return map_; }
    const YamlReader& reader() const { return reader_; }

    bool has(const std::string& key) const { return find(key) != nullptr; }
    const Entry* find(const std::string& key) const;
    const Entry& required(const std::string& key) const;  // missing: error at the map
    // The value of a required key; an empty (null) value is an error at the key,
    // because yaml-cpp marks an empty value at the start of the next line.
    YAML::Node value(const std::string& key) const;

    double number(const std::string& key) const;
    double number_or(const std::string& key, double fallback) const;
    double number_at_least(const std::string& key, double min) const;
    double positive(const std::string& key) const;
    double number_up_to(const std::string& key, double min, double max) const;
    double positive_up_to(const std::string& key, double max) const;
    int integer(const std::string& key, int min, int max) const;
    bool boolean_or(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    dvec3 vec3(const std::string& key) const;
    dvec3 color(const std::string& key) const;
    dvec3 direction(const std::string& key) const;

private:
    const YamlReader& reader_;
    YAML::Node map_;
    std::string what_;
    std::vector<Entry> entries_;
};

}  // namespace fh
