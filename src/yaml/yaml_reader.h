// Strict reading of YAML files on top of yaml-cpp, shared by the scene and
// movie loaders. Every error is an fh::InputError carrying the file and the
// 1-based line and column of the offending key or value (yaml-cpp's marks are
// 0-based), so a typo is reported where it is, never passed over silently.
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/vec.h"
#include "text/closest_match.h"  // the loaders' "did you mean" hints
#include "text/input_error.h"
#include "text/text_input.h"

namespace fh {

// Maps and lists nested deeper than this are refused (the formats need 5).
// The limits on the file itself (size, encoding) are in text/text_input.h.
inline constexpr int kMaxYamlNesting = 64;

// Reads values of one file; knows the file name to put in front of errors.
class YamlReader {
public:
    explicit YamlReader(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    // Reads and parses the whole file: one YAML document whose top level is a
    // map. Unreadable file, syntax error, empty file or another top level: InputError.
    YAML::Node load_map(const std::string& what) const;
    // The same for text in memory (file() only names it in errors). The text
    // is checked as read_input_file checks a file's, then its nesting depth
    // (at most kMaxYamlNesting) before it is turned into nodes.
    YAML::Node parse_map(const std::string& text, const std::string& what) const;

    [[noreturn]] void fail(const YAML::Mark& mark, const std::string& message) const;
    [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;

    // Scalars and vectors. `name` is how the value is called in messages
    // (usually its key). Quoted scalars ("1") are text, never numbers.
    double number(const YAML::Node& node, const std::string& name) const;  // finite
    double number_at_least(const YAML::Node& node, const std::string& name, double min) const;
    double positive(const YAML::Node& node, const std::string& name) const;  // finite, > 0
    double number_up_to(const YAML::Node& node, const std::string& name, double min, double max) const;  // min..max
    double positive_up_to(const YAML::Node& node, const std::string& name, double max) const;  // > 0, <= max
    int integer(const YAML::Node& node, const std::string& name, int min, int max) const;
    bool boolean(const YAML::Node& node, const std::string& name) const;
    std::string string(const YAML::Node& node, const std::string& name) const;
    std::string file_name(const YAML::Node& node, const std::string& name) const;  // a string, not empty
    dvec3 vec3(const YAML::Node& node, const std::string& name) const;       // 3 finite numbers
    dvec3 color(const YAML::Node& node, const std::string& name) const;      // 3 numbers in 0..255
    dvec3 direction(const YAML::Node& node, const std::string& name) const;  // non-zero, as given

    // One of `options`, by index; `what` names the kind ("surface type").
    int choice(const YAML::Node& node, const std::string& what,
               const std::vector<std::string>& options) const;

    void expect_map(const YAML::Node& node, const std::string& name) const;
    void expect_list(const YAML::Node& node, const std::string& name) const;

private:
    std::string file_;
};

// The end of a wrong-type message: "got a list", "got 'abc'", "got nothing".
std::string got(const YAML::Node& node);

// A yaml-cpp exception that escaped the checks above, as bad input at its
// position: no yaml-cpp exception may leave a loader.
InputError to_input_error(const std::string& file, const YAML::Exception& e);

}  // namespace fh
