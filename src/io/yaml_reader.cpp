#include "io/yaml_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <yaml-cpp/depthguard.h>

namespace fh {

namespace {

std::string read_text(const std::string& path) {
    std::error_code ec;
    // Opening a directory succeeds on Linux and then reads nothing; say why.
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "cannot read file: is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::string reason = std::strerror(errno);
        if (!reason.empty()) reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
        throw InputError(path, "cannot read file: " + reason);
    }
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw InputError(path, "cannot read file: read error");
    return text;
}

// A quoted scalar ("1") is text even when it looks like a number.
bool is_text(const YAML::Node& node) {
    return node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str";
}

enum class Parsed { ok, not_a_number, not_finite };

// YAML's spellings of infinity and not-a-number, which from_chars does not know.
bool is_yaml_nonfinite(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    return s == ".inf" || s == ".Inf" || s == ".INF" || s == ".nan" || s == ".NaN" || s == ".NAN";
}

Parsed parse_double(std::string_view s, double& out) {
    if (is_yaml_nonfinite(s)) return Parsed::not_finite;
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);  // from_chars refuses a '+'
    if (s.empty() || s.front() == '+' || s.front() == ' ') return Parsed::not_a_number;
    const char* end = s.data() + s.size();
    const auto [ptr, ec] = std::from_chars(s.data(), end, out);
    if (ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range)) return Parsed::not_a_number;
    // Out of range is overflow (not finite) or underflow (a value near 0):
    // strtod tells which.
    if (ec == std::errc::result_out_of_range) out = std::strtod(std::string(s).c_str(), nullptr);
    return std::isfinite(out) ? Parsed::ok : Parsed::not_finite;
}

bool is_one_of(const std::string& s, std::initializer_list<const char*> words) {
    return std::any_of(words.begin(), words.end(), [&](const char* w) { return s == w; });
}

std::string quoted_list(const std::vector<std::string>& options) {
    std::string s;
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (i > 0) s += (i + 1 == options.size()) ? " or " : ", ";
        s += options[i];
    }
    return s;
}

}  // namespace

YAML::Node YamlReader::load_map(const std::string& what) const {
    const std::string text = read_text(file_);
    std::vector<YAML::Node> docs;
    try {
        docs = YAML::LoadAll(text);
    } catch (const YAML::Exception& e) {
        throw to_input_error(file_, e);
    }
    if (docs.empty() || docs.front().IsNull()) throw InputError(file_, "empty " + what + " file");
    if (docs.size() > 1) fail(docs[1], "expected a single yaml document");
    if (!docs.front().IsMap()) fail(docs.front(), "expected a map at the top level, " + got(docs.front()));
    return docs.front();
}

void YamlReader::fail(const YAML::Mark& mark, const std::string& message) const {
    if (mark.is_null()) throw InputError(file_, message);
    throw InputError(file_, mark.line + 1, mark.column + 1, message);
}

void YamlReader::fail(const YAML::Node& node, const std::string& message) const {
    fail(node.Mark(), message);
}

double YamlReader::number(const YAML::Node& node, const std::string& name) const {
    double value = 0;
    const Parsed p = (node.IsScalar() && !is_text(node)) ? parse_double(node.Scalar(), value)
                                                         : Parsed::not_a_number;
    if (p == Parsed::not_a_number) fail(node, "expected a number for '" + name + "', " + got(node));
    if (p == Parsed::not_finite) fail(node, "'" + name + "' must be finite");
    return value;
}

double YamlReader::number_at_least(const YAML::Node& node, const std::string& name, double min) const {
    const double value = number(node, name);
    if (value < min) {
        std::string bound = std::to_string(min);
        if (min == std::floor(min)) bound = std::to_string(static_cast<long long>(min));
        fail(node, "'" + name + "' must be >= " + bound + ", got " + node.Scalar());
    }
    return value;
}

double YamlReader::positive(const YAML::Node& node, const std::string& name) const {
    const double value = number(node, name);
    if (!(value > 0)) fail(node, "'" + name + "' must be > 0, got " + node.Scalar());
    return value;
}

int YamlReader::integer(const YAML::Node& node, const std::string& name, int min, int max) const {
    long long value = 0;
    bool ok = node.IsScalar() && !is_text(node);
    bool in_range = true;
    if (ok) {
        std::string_view s = node.Scalar();
        if (!s.empty() && s.front() == '+') s.remove_prefix(1);
        const char* end = s.data() + s.size();
        const auto [ptr, ec] = std::from_chars(s.data(), end, value);
        ok = !s.empty() && ptr == end && (ec == std::errc() || ec == std::errc::result_out_of_range);
        in_range = ec == std::errc() && value >= min && value <= max;
    }
    if (!ok) fail(node, "expected an integer for '" + name + "', " + got(node));
    if (!in_range) {
        const std::string range = max == INT_MAX ? ">= " + std::to_string(min)
                                                 : "between " + std::to_string(min) + " and " + std::to_string(max);
        fail(node, "'" + name + "' must be " + range + ", got " + node.Scalar());
    }
    return static_cast<int>(value);
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& name) const {
    if (node.IsScalar() && !is_text(node)) {
        if (is_one_of(node.Scalar(), {"true", "True", "TRUE"})) return true;
        if (is_one_of(node.Scalar(), {"false", "False", "FALSE"})) return false;
    }
    fail(node, "expected true or false for '" + name + "', " + got(node));
}

std::string YamlReader::string(const YAML::Node& node, const std::string& name) const {
    if (!node.IsScalar()) fail(node, "expected a name for '" + name + "', " + got(node));
    return node.Scalar();
}

dvec3 YamlReader::vec3(const YAML::Node& node, const std::string& name) const {
    if (!node.IsSequence() || node.size() != 3) fail(node, "expected a list of 3 numbers for '" + name + "'");
    return {number(node[0], name), number(node[1], name), number(node[2], name)};
}

dvec3 YamlReader::color(const YAML::Node& node, const std::string& name) const {
    const dvec3 c = vec3(node, name);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0 || c[i] > 255)
            fail(node[i], "'" + name + "' components must be in 0..255, got " + node[i].Scalar());
    return c;
}

dvec3 YamlReader::direction(const YAML::Node& node, const std::string& name) const {
    const dvec3 d = vec3(node, name);
    if (max_abs_component(d) == 0) fail(node, "'" + name + "' must not be zero-length");
    return d;
}

int YamlReader::choice(const YAML::Node& node, const std::string& what,
                       const std::vector<std::string>& options) const {
    const std::string word = string(node, what);
    for (std::size_t i = 0; i < options.size(); ++i)
        if (options[i] == word) return static_cast<int>(i);
    const std::string hint = closest_match(word, options);
    fail(node, "unknown " + what + " '" + word + "' (" +
                   (hint.empty() ? "expected " + quoted_list(options) : "did you mean '" + hint + "'?") + ")");
}

void YamlReader::expect_map(const YAML::Node& node, const std::string& name) const {
    if (!node.IsMap()) fail(node, "expected a map for " + name + ", " + got(node));
}

void YamlReader::expect_list(const YAML::Node& node, const std::string& name) const {
    if (!node.IsSequence()) fail(node, "expected a list for " + name + ", " + got(node));
}

std::string got(const YAML::Node& node) {
    if (node.IsSequence()) return "got a list";
    if (node.IsMap()) return "got a map";
    if (node.IsScalar()) return "got '" + node.Scalar() + "'";
    return "got nothing";
}

InputError to_input_error(const std::string& file, const YAML::Exception& e) {
    // yaml-cpp's depth guard says "bad file"; say what is wrong instead.
    const bool too_deep = dynamic_cast<const YAML::DeepRecursion*>(&e) != nullptr;
    const std::string message = "invalid yaml: " + (too_deep ? std::string("nested too deeply") : e.msg);
    if (e.mark.is_null()) return InputError(file, message);
    return InputError(file, e.mark.line + 1, e.mark.column + 1, message);
}

int edit_distance(const std::string& a, const std::string& b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            // A swap of two neighbours ("cmaera") is one typo, not two.
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

std::string closest_match(const std::string& word, const std::vector<std::string>& options) {
    std::string best;
    int best_distance = INT_MAX;
    for (const std::string& option : options) {
        const int dist = edit_distance(word, option);
        // At most 2 edits, and not more than half the word: "u" may be "up",
        // but "x" is not "up".
        if (dist <= 2 && dist <= static_cast<int>(option.size()) / 2 && dist < best_distance) {
            best = option;
            best_distance = dist;
        }
    }
    return best;
}

}  // namespace fh
