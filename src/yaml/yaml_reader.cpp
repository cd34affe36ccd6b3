#include "yaml/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <unordered_map>
#include <vector>

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

// What both nesting checks below say.
std::string too_deep_message() {
    return "maps and lists nested more than " + std::to_string(kMaxYamlNesting) + " levels deep";
}

// Follows the parser's events and refuses maps and lists nested deeper than
// kMaxYamlNesting as soon as the first one opens, so the recursive parser
// never goes deeper either. Aliases count as what they stand for: yaml-cpp
// shares an aliased node, but the readers walk it once for each alias --
// ten groups of ten aliases of the group before describe 10^10 spheres in
// a kilobyte, and a group that held an alias of itself (yaml-cpp records
// the anchor as the group opens) made the surface reader recurse until the
// stack ran out. So an alias inside what it names is refused, an alias
// adds its anchor's depth to where it stands, and all aliases together may
// stand for at most kMaxAliasedValues values.
class NestingCheck : public YAML::EventHandler {
public:
    explicit NestingCheck(const std::string& file) : file_(file) {}

    YAML::Mark document_start() const { return document_start_; }

    void OnDocumentStart(const YAML::Mark& mark) override {
        open_.clear();
        document_start_ = mark;
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t anchor) override { value(anchor); }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        const auto it = anchors_.find(anchor);
        if (it == anchors_.end()) return;  // yaml-cpp refuses it
        if (it->second.values == kOpen) refuse(mark, "an alias inside the map or list it names");
        if (int(open_.size()) + it->second.height > kMaxYamlNesting) refuse(mark, too_deep_message());
        aliased_ += std::min(kMaxAliasedValues + 1, it->second.values);  // at most the limit before: no overflow
        if (aliased_ > kMaxAliasedValues)
            refuse(mark, "aliases standing for more than " + std::to_string(kMaxAliasedValues) +
                             " values in all (each alias is read as a copy)");
        add(it->second.values, it->second.height);
    }
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t anchor, const std::string&) override {
        value(anchor);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override {
        open(mark, anchor);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override {
        open(mark, anchor);
    }
    void OnMapEnd() override { close(); }

private:
    static constexpr std::uint64_t kMaxAliasedValues = 1'000'000;
    static constexpr std::uint64_t kOpen = ~std::uint64_t(0);
    struct Size {
        std::uint64_t values = 1;  // itself and all inside it, aliases as what they stand for
        int height = 0;            // levels of maps and lists, itself included
    };
    struct Open {
        YAML::anchor_t anchor;
        Size size;
    };

    [[noreturn]] void refuse(const YAML::Mark& mark, const std::string& message) const {
        if (mark.is_null()) throw InputError(file_, message);
        throw InputError(file_, mark.line + 1, mark.column + 1, message);
    }
    void add(std::uint64_t values, int height) {
        if (open_.empty()) return;
        Size& s = open_.back().size;
        s.values = std::min(kOpen - 1, s.values + values);
        s.height = std::max(s.height, height + 1);
    }
    void value(YAML::anchor_t anchor) {
        if (anchor != YAML::NullAnchor) anchors_[anchor] = Size{1, 0};
        add(1, 0);
    }
    void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
        if (int(open_.size()) + 1 > kMaxYamlNesting) refuse(mark, too_deep_message());
        if (anchor != YAML::NullAnchor) anchors_[anchor] = Size{kOpen, 0};
        open_.push_back({anchor, Size{1, 1}});
    }
    void close() {
        if (open_.empty()) return;  // (yaml-cpp's events are balanced)
        const Open done = open_.back();
        open_.pop_back();
        if (done.anchor != YAML::NullAnchor) anchors_[done.anchor] = done.size;
        add(done.size.values, done.size.height);
    }

    const std::string& file_;
    std::vector<Open> open_;
    std::unordered_map<YAML::anchor_t, Size> anchors_;
    std::uint64_t aliased_ = 0;
    YAML::Mark document_start_ = YAML::Mark::null_mark();
};

// yaml-cpp's scanner turns the whole text into tokens before the parser
// sees the first event when a flow list or map opens and never closes: 240
// bytes a '[' (16 MiB of them: 28 s and 4 GB before the nesting check above
// could refuse them). So flow brackets are counted first, outside quotes
// and comments, against the same limit, the file's top-level map its first
// level, as the check above counts; '[' and '{' inside a plain value count
// too (64 of them open at once is no scene).
void check_flow_nesting(const std::string& file, const std::string& text) {
    int depth = 0, line = 1, column = 0;
    char quote = 0;
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        ++column;
        if (c == '\n') {
            ++line, column = 0, comment = false;
            continue;
        }
        if (comment) continue;
        if (quote) {
            if (c == '\\' && quote == '"') ++i, ++column;  // an escape in double quotes
            else if (c == quote) quote = 0;
            continue;
        }
        // A quote opens a quoted value only where a value starts.
        const char before = i == 0 ? '\n' : text[i - 1];
        const bool blank = before == ' ' || before == '\t' || before == '\n' || before == '\r';
        const bool starts = blank || before == '[' || before == '{' || before == ',' || before == ':' || before == '-';
        if ((c == '"' || c == '\'') && starts) quote = c;
        else if (c == '#' && blank) comment = true;
        else if ((c == '[' || c == '{') && 1 + ++depth > kMaxYamlNesting)
            throw InputError(file, line, column, too_deep_message());
        else if ((c == ']' || c == '}') && depth > 0) --depth;
    }
}

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
        check_flow_nesting(file_, text);
        check_structure(file_, text);  // first: nesting, at most one document, aliases
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

namespace {
// 1e12, 255: a limit as the docs write it.
std::string limit_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    std::string s = text;
    if (const size_t plus = s.find("e+"); plus != std::string::npos) s.erase(plus + 1, 1);
    return s;
}
}  // namespace

double YamlReader::number_up_to(const YAML::Node& node, const std::string& name, double min, double max) const {
    const double value = number_at_least(node, name, min);
    if (value > max) fail(node, "'" + name + "' must be at most " + limit_text(max) + ", got " + node.Scalar());
    return value;
}

double YamlReader::positive_up_to(const YAML::Node& node, const std::string& name, double max) const {
    const double value = positive(node, name);
    if (value > max) fail(node, "'" + name + "' must be at most " + limit_text(max) + ", got " + node.Scalar());
    return value;
}

int YamlReader::integer(const YAML::Node& node, const std::string& name, int min, int max) const {
    long long value = 0;
    bool ok = node.IsScalar() && !is_text(node);
    bool in_range = true, too_large = false;
    if (ok) {
        std::string_view s = node.Scalar();
        if (!s.empty() && s.front() == '+') s.remove_prefix(1);
        const char* end = s.data() + s.size();
        const auto [ptr, ec] = std::from_chars(s.data(), end, value);
        ok = !s.empty() && ptr == end && (ec == std::errc() || ec == std::errc::result_out_of_range);
        in_range = ec == std::errc() && value >= min && value <= max;
        too_large = ec == std::errc::result_out_of_range || value > max;
    }
    if (!ok) fail(node, "expected an integer for '" + name + "', " + got(node));
    if (!in_range) {
        // (">= 0" for 99999999999999999999 would read as if it were below 0.)
        const std::string range = max == INT_MAX && !too_large
                                      ? ">= " + std::to_string(min)
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

std::string YamlReader::file_name(const YAML::Node& node, const std::string& name) const {
    std::string file = string(node, name);
    if (file.empty()) fail(node, "'" + name + "' names no file (it is empty)");
    return file;
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
