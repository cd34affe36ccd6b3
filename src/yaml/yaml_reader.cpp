#include "yaml/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include "yaml/yaml_hints.h"

namespace fh {

namespace {

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

// The character at a yaml-cpp mark (0-based line, column in characters), for
// messages; "" when there is none.
std::string char_at(const std::string& text, const YAML::Mark& mark) {
    std::size_t i = 0;
    for (int line = 0; line < mark.line && i < text.size(); ++i)
        if (text[i] == '\n') ++line;
    for (int col = 0; col < mark.column && i < text.size(); ++col) i += std::max<std::size_t>(1, utf8_length(text, i));
    if (i >= text.size()) return "";
    return text.substr(i, std::max<std::size_t>(1, utf8_length(text, i)));
}

// Follows the parser's events and refuses maps and lists nested deeper than
// kMaxYamlNesting as soon as the first one opens, so the recursive parser
// never goes deeper either. Aliases are not expanded.
class NestingCheck : public YAML::EventHandler {
public:
    explicit NestingCheck(const std::string& file) : file_(file) {}

    YAML::Mark document_start() const { return document_start_; }

    void OnDocumentStart(const YAML::Mark& mark) override {
        depth_ = 0;
        document_start_ = mark;
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {
        open(mark);
    }
    void OnSequenceEnd() override { --depth_; }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        open(mark);
    }
    void OnMapEnd() override { --depth_; }

private:
    void open(const YAML::Mark& mark) {
        if (++depth_ <= kMaxYamlNesting) return;
        const std::string message =
            "maps and lists nested more than " + std::to_string(kMaxYamlNesting) + " levels deep";
        if (mark.is_null()) throw InputError(file_, message);
        throw InputError(file_, mark.line + 1, mark.column + 1, message);
    }

    const std::string& file_;
    int depth_ = 0;
    YAML::Mark document_start_ = YAML::Mark::null_mark();
};

// " (HINT)" when yaml/yaml_hints.h finds a common mistake behind yaml-cpp's
// error `yaml_message` at `mark` of `text`, else "": yaml-cpp's words ("end of
// map not found") rarely name the cause (a tab, a missing colon, ...).
std::string hint_for(const std::string& text, const YAML::Mark& mark, const std::string& yaml_message) {
    const std::string hint = mark.is_null() ? yaml_hint(text, 0, 0, yaml_message)
                                            : yaml_hint(text, mark.line + 1, mark.column + 1, yaml_message);
    return hint.empty() ? "" : " (" + hint + ")";
}

// A yaml-cpp exception as bad input at its position; with the file's `text`
// at hand, a hint is added where one is found.
InputError yaml_error(const std::string& file, const YAML::Exception& e, const std::string* text) {
    // yaml-cpp's depth guard says "bad file"; say what is wrong instead.
    const bool too_deep = dynamic_cast<const YAML::DeepRecursion*>(&e) != nullptr;
    std::string message = "invalid yaml: " + (too_deep ? std::string("nested too deeply") : e.msg);
    if (text && !too_deep) message += hint_for(*text, e.mark, e.msg);
    if (e.mark.is_null()) return InputError(file, message);
    return InputError(file, e.mark.line + 1, e.mark.column + 1, message);
}

// Runs the parser over the text once before any node is built: refuses deep
// nesting (above) and a second document. This also guards against a bug of
// yaml-cpp 0.7 (jbeder/yaml-cpp#1040, fixed upstream in 2024 by #1319): a
// token that cannot start a value, such as a ',' outside brackets, is not
// consumed, and the parser reports an empty document for it again and again,
// so YAML::LoadAll loops forever and eats memory. Here parsing stops at the
// second document, whatever it is.
void check_structure(const std::string& file, const std::string& text) {
    std::istringstream in(text);
    YAML::Parser parser(in);
    NestingCheck check(file);
    if (!parser.HandleNextDocument(check)) return;  // no document at all
    const YAML::Mark first = check.document_start();
    if (!parser.HandleNextDocument(check)) return;
    const YAML::Mark second = check.document_start();
    const std::string c = char_at(text, second);
    const bool stuck = second.pos == first.pos;  // nothing consumed: the bug above
    const bool cannot_start = c == "," || c == "]" || c == "}";
    const std::string unexpected = "unexpected '" + c + "'";
    const std::string message = (stuck || cannot_start)
                                    ? "invalid yaml: " + unexpected + hint_for(text, second, unexpected)
                                    : "expected a single yaml document";
    if (second.is_null()) throw InputError(file, message);
    throw InputError(file, second.line + 1, second.column + 1, message);
}

}  // namespace

YAML::Node YamlReader::load_map(const std::string& what) const { return parse_map(read_input_file(file_), what); }

YAML::Node YamlReader::parse_map(const std::string& text, const std::string& what) const {
    check_input_text(file_, text);
    YAML::Node root;
    try {
        check_structure(file_, text);  // first: nesting, at most one document
        root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw yaml_error(file_, e, &text);
    }
    if (root.IsNull()) throw InputError(file_, "empty " + what + " file");
    if (!root.IsMap()) fail(root, "expected a map at the top level, " + got(root));
    return root;
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
    if (node.IsScalar()) return "got '" + printable(node.Scalar(), 60) + "'";
    return "got nothing";
}

InputError to_input_error(const std::string& file, const YAML::Exception& e) { return yaml_error(file, e, nullptr); }

}  // namespace fh
