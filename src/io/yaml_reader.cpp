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
#include <cstdio>
#include <sstream>

#include <sys/stat.h>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

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

std::string lowercase_first(std::string s) {
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

std::string hex_byte(unsigned char c) {
    static const char hex[] = "0123456789abcdef";
    return std::string("0x") + hex[c >> 4] + hex[c & 15];
}

// The length of the valid UTF-8 character at text[i], or 0 when the bytes
// there are not one (overlong forms, surrogates and values past U+10FFFF are
// not), or when it is a C1 control character (U+0080..U+009F, not allowed in
// YAML but for U+0085).
std::size_t utf8_length(const std::string& text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const unsigned c = byte(i);
    const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) {
        return byte(k) >= lo && byte(k) <= hi;
    };
    if (c < 0x80) return 1;
    if (c == 0xc2) return (cont(i + 1, 0xa0) || byte(i + 1) == 0x85) ? 2 : 0;
    if (c >= 0xc3 && c <= 0xdf) return cont(i + 1) ? 2 : 0;
    if (c == 0xe0) return cont(i + 1, 0xa0) && cont(i + 2) ? 3 : 0;
    if (c == 0xed) return cont(i + 1, 0x80, 0x9f) && cont(i + 2) ? 3 : 0;
    if (c >= 0xe1 && c <= 0xef) return cont(i + 1) && cont(i + 2) ? 3 : 0;
    if (c == 0xf0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c >= 0xf1 && c <= 0xf3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c == 0xf4) return cont(i + 1, 0x80, 0x8f) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    return 0;
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
    const std::string message = (stuck || cannot_start) ? "invalid yaml: unexpected '" + c + "'"
                                                        : "expected a single yaml document";
    if (second.is_null()) throw InputError(file, message);
    throw InputError(file, second.line + 1, second.column + 1, message);
}

}  // namespace

void check_input_text(const std::string& file, const std::string& text) {
    if (text.size() > kMaxInputBytes)
        throw InputError(file, "file too large: " + std::to_string(text.size()) + " bytes (the limit is " +
                                   std::to_string(kMaxInputBytes) + " bytes, 1 MiB)");
    int line = 1, column = 1;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            column = 1;
            ++i;
            continue;
        }
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f)
            throw InputError(file, line, column,
                             "binary data, not text: control byte " + hex_byte(c) +
                                 " (scene and movie files are UTF-8 text)");
        const std::size_t length = utf8_length(text, i);
        if (length == 0)
            throw InputError(file, line, column,
                             "not UTF-8 text: byte " + hex_byte(c) + " (scene and movie files are UTF-8 text)");
        i += length;
        ++column;
    }
}

std::string read_input_file(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(errno)));
    // Opening a folder succeeds on Linux and then reads nothing; a device or a
    // pipe may never end. Say why instead.
    if (S_ISDIR(st.st_mode)) throw InputError(path, "cannot read file: is a directory");
    if (!S_ISREG(st.st_mode)) throw InputError(path, "cannot read file: not a regular file");
    if (static_cast<unsigned long long>(st.st_size) > kMaxInputBytes)
        throw InputError(path, "file too large: " + std::to_string(st.st_size) + " bytes (the limit is " +
                                   std::to_string(kMaxInputBytes) + " bytes, 1 MiB)");
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(errno)));
    // At most one byte past the limit, should the file have grown since.
    std::string text(kMaxInputBytes + 1, '\0');
    const std::size_t n = std::fread(text.data(), 1, text.size(), f);
    const bool failed = std::ferror(f) != 0;
    const int read_errno = errno;
    std::fclose(f);
    if (failed) throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(read_errno)));
    text.resize(n);
    check_input_text(path, text);
    return text;
}

YAML::Node YamlReader::load_map(const std::string& what) const { return parse_map(read_input_file(file_), what); }

YAML::Node YamlReader::parse_map(const std::string& text, const std::string& what) const {
    check_input_text(file_, text);
    YAML::Node root;
    try {
        check_structure(file_, text);  // first: nesting, at most one document
        root = YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw to_input_error(file_, e);
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
    // The distance is at least the difference in length: long words (a name
    // may be a megabyte) are never compared at quadratic cost.
    if (word.size() > 64) return best;
    for (const std::string& option : options) {
        if (option.size() > word.size() + 2 || word.size() > option.size() + 2) continue;
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
