#include "yaml/yaml_hints.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace fh {

namespace {

constexpr auto npos = std::string_view::npos;

// One line of the text ('\n' ends a line; a '\r' before it is dropped).
struct Line {
    std::string_view text;
    std::size_t indent = 0;  // leading spaces and tabs, in bytes
    bool tab_in_indent = false;
    bool in_flow = false;  // starts inside a [...] or {...} begun on an earlier line
    bool empty = true;     // blank, or only a comment
    bool block() const { return !empty && !in_flow; }
};

// A bracket or quote: its character, 1-based line and byte in that line.
struct Mark {
    char c = 0;  // 0 = none
    int line = 0;
    std::size_t byte = 0;
};

// What one pass over the whole text finds.
struct Scan {
    std::vector<Line> lines;
    Mark unclosed_quote;             // the first
    Mark bad_closer, its_opener;     // the first closer that does not fit, and what was open then
    std::vector<Mark> open;          // brackets still open at the end
    std::size_t open_since_error = 0;  // open[0..this) stayed open from the error to the end
};

bool is_space(char c) { return c == ' ' || c == '\t'; }
bool is_flow_char(char c) { return c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'; }

// The byte closing the quoted scalar opened at `i`, or npos: our formats never
// continue a quoted scalar on the next line.
std::size_t closing_quote(std::string_view t, std::size_t i) {
    for (std::size_t k = i + 1; k < t.size(); ++k) {
        if (t[i] == '"' && t[k] == '\\') ++k;  // skip the escaped character
        else if (t[k] == t[i] && t[i] == '\'' && k + 1 < t.size() && t[k + 1] == '\'') ++k;  // '' is a quote
        else if (t[k] == t[i]) return k;
    }
    return npos;
}

// Follows quotes, comments and flow brackets line by line. Outside a flow, a
// bracket inside plain text ("a[1]") is text and a quote is one only where a
// value starts ("don't" is text), as in YAML; inside a flow, brackets always count.
Scan scan(const std::string& text, int error_line, int error_column) {
    Scan s;
    bool past_error = false;
    const auto reach_error = [&] {
        if (!past_error) s.open_since_error = s.open.size();
        past_error = true;
    };
    for (std::size_t start = 0, end = 0; end < text.size(); start = end + 1) {
        end = std::min(text.find('\n', start), text.size());
        Line line;
        line.text = std::string_view(text).substr(start, end - start);
        if (!line.text.empty() && line.text.back() == '\r') line.text.remove_suffix(1);
        const std::string_view t = line.text;
        const int n = static_cast<int>(s.lines.size()) + 1;
        line.in_flow = !s.open.empty();
        for (; line.indent < t.size() && is_space(t[line.indent]); ++line.indent)
            if (t[line.indent] == '\t') line.tab_in_indent = true;
        line.empty = line.indent == t.size() || t[line.indent] == '#';
        bool value_start = true;  // where a scalar or a collection may begin
        bool in_text = false;     // inside a plain (unquoted) scalar
        for (std::size_t i = line.indent; !line.empty && i < t.size(); ++i) {
            if (n == error_line && i + 1 >= static_cast<std::size_t>(std::max(error_column, 1))) reach_error();
            const char c = t[i];
            const char next = i + 1 < t.size() ? t[i + 1] : ' ';
            const bool flow = !s.open.empty();
            if (is_space(c)) continue;
            if (c == '#' && is_space(t[i - 1])) break;  // a comment (i > indent here)
            if ((c == '"' || c == '\'') && value_start) {
                const std::size_t close = closing_quote(t, i);
                if (close == npos) {
                    if (s.unclosed_quote.c == 0) s.unclosed_quote = {c, n, i};
                    break;
                }
                i = close;
                value_start = false;
            } else if ((c == '[' || c == '{') && (flow || !in_text)) {
                s.open.push_back({c, n, i});
                value_start = true, in_text = false;
            } else if ((c == ']' || c == '}') && (flow || !in_text)) {
                const char opener = c == ']' ? '[' : '{';
                if ((s.open.empty() || s.open.back().c != opener) && s.bad_closer.c == 0) {
                    s.bad_closer = {c, n, i};
                    if (!s.open.empty()) s.its_opener = s.open.back();
                }
                if (!s.open.empty()) s.open.pop_back();
                if (past_error) s.open_since_error = std::min(s.open_since_error, s.open.size());
                value_start = in_text = false;
            } else if ((c == ',' && flow) || (c == ':' && (is_space(next) || (flow && is_flow_char(next))))) {
                value_start = true, in_text = false;
            } else if (!((c == '-' || c == '?') && value_start && is_space(next))) {
                value_start = false, in_text = true;  // plain text; "- " and "? " keep a value's start
            }
        }
        if (n == error_line) reach_error();
        s.lines.push_back(line);
    }
    reach_error();  // the error is at the end (or its place unknown)
    return s;
}

// "line 18, column 5", the column in characters.
std::string place(const Scan& s, const Mark& m) {
    int column = 1;
    for (char c : s.lines[m.line - 1].text.substr(0, m.byte))
        if ((static_cast<unsigned char>(c) & 0xc0) != 0x80) ++column;  // not a UTF-8 continuation byte
    return "line " + std::to_string(m.line) + ", column " + std::to_string(column);
}

// The line without its indentation, trailing comment and trailing spaces.
std::string_view content(const Line& l) {
    std::string_view t = l.text.substr(l.indent);
    for (std::size_t i = 1; i < t.size(); ++i)
        if (t[i] == '#' && is_space(t[i - 1])) t = t.substr(0, i);
    return t.substr(0, t.find_last_not_of(" \t") + 1);
}

// A missing colon, or a missing space after one, on block line `n`.
std::string colon_hint(const std::vector<Line>& lines, int n) {
    const Line& l = lines[n - 1];
    const std::string_view t = content(l);
    const std::string at = "line " + std::to_string(n) + ": ";
    // "scene:scene.yaml": a name, a colon and no space, first on the line or in a "- " item.
    std::string_view item = t;
    while (item.size() >= 2 && item[0] == '-' && is_space(item[1]))
        item = item.substr(item.find_first_not_of(" \t", 1));
    const std::string_view token = item.substr(0, std::min(item.find_first_of(" \t"), item.size()));
    const std::size_t colon = token.find(':');
    if (colon != npos && colon > 0 && colon + 1 < token.size() &&
        std::all_of(token.begin(), token.begin() + colon, is_name_char)) {
        const std::string fixed = std::string(token.substr(0, colon + 1)) + " " + std::string(token.substr(colon + 1));
        return at + "put a space after the colon in '" + std::string(token) + "' ('" + fixed + "')";
    }
    // "materials" above a deeper line, "red {...}" or "fps 3": a name without its colon.
    std::size_t name_end = 0;
    while (name_end < t.size() && is_name_char(t[name_end])) ++name_end;
    const std::string name(t.substr(0, name_end));
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return "";
    const std::string_view rest = t.substr(name_end);
    const std::string no_colon = at + "'" + name + "' has no colon; write '" + name + ":'";
    if (rest.empty()) {
        const auto next = std::find_if(lines.begin() + n, lines.end(), [](const Line& x) { return !x.empty; });
        return next != lines.end() && next->indent > l.indent ? no_colon : "";
    }
    if (!is_space(rest[0])) return "";
    const std::string value(rest.substr(rest.find_first_not_of(" \t")));  // not empty: trailing spaces are cut
    if (value[0] == '{' || value[0] == '[') return no_colon;
    if (value.find(':') != npos) return "";
    return at + "'" + name + " " + value + "' has no colon; write '" + name + ": " + value + "'";
}

// Line `n`'s indentation against the block line before it, when the error is
// at the line's first word: there yaml-cpp notices a misindented line.
std::string indent_hint(const std::vector<Line>& lines, int n, int column, bool precise_only) {
    const Line& l = lines[n - 1];
    const std::size_t word_end = std::min(l.text.find_first_of(" \t", l.indent), l.text.size());
    if (column < 1 || static_cast<std::size_t>(column) > word_end + 1) return "";
    const std::string rule = "keys of one map, and items of one list, start in the same column";
    const std::string vague = "check the indentation of line " + std::to_string(n) + ": " + rule;
    int m = n - 1;
    while (m > 0 && !lines[m - 1].block()) --m;
    if (m == 0) return precise_only ? "" : vague;
    const Line& prev = lines[m - 1];
    const std::string_view prev_text = content(prev);
    // Deeper than "key:" is nesting; so is a "- " item's own column, and
    // deeper than that is no simple misalignment.
    const std::size_t item_column = prev.text.find_first_not_of("- \t", prev.indent);
    const bool nests = l.indent > prev.indent &&
                       (prev_text.back() == ':' || (prev_text[0] == '-' && l.indent >= item_column));
    if (l.indent == prev.indent || nests) return precise_only ? "" : vague;
    return "line " + std::to_string(n) + " is indented by " + std::to_string(l.indent) +
           (l.indent == 1 ? " space" : " spaces") + " and line " + std::to_string(m) + " by " +
           std::to_string(prev.indent) + ": " + rule;
}

}  // namespace

std::string yaml_hint(const std::string& text, int line, int column, const std::string& message) {
    const Scan s = scan(text, line, column);
    const int count = static_cast<int>(s.lines.size());
    const int last = line > 0 && line <= count ? line : count;  // the lines the error may come from
    for (int n = 1; n <= last; ++n)
        if (s.lines[n - 1].tab_in_indent && s.lines[n - 1].block())
            return "line " + std::to_string(n) + " is indented with a tab; YAML indents with spaces only";
    if (s.unclosed_quote.c != 0 && s.unclosed_quote.line <= last)
        return "the quote opened at " + place(s, s.unclosed_quote) + " is not closed on its line";
    const auto quoted = [](char c) { return std::string("'") + c + "'"; };
    if (s.bad_closer.c != 0 && s.bad_closer.line <= last) {
        const std::string closer = quoted(s.bad_closer.c) + " at " + place(s, s.bad_closer);
        if (s.its_opener.c == 0) return "the " + closer + " closes nothing";
        return "the " + quoted(s.its_opener.c) + " at " + place(s, s.its_opener) + " is closed by " + closer;
    }
    if (s.bad_closer.c == 0 && s.open_since_error > 0) {
        const Mark& innermost = s.open[s.open_since_error - 1];
        return "the " + quoted(innermost.c) + " at " + place(s, innermost) + " is never closed";
    }
    // The rest is about block structure: indentation and colons.
    const bool map_value = message == "illegal map value";
    if (!(map_value || message == "end of map not found" || message == "end of sequence not found" ||
          message == "illegal block entry" || message == "illegal map key") ||
        line < 1 || line > count)
        return "";
    // The error line, then the line before it: yaml-cpp often notices a
    // missing colon only on the next line.
    int before = line - 1;
    while (before > 0 && s.lines[before - 1].empty) --before;
    for (const int n : {line, before})
        if (n > 0 && s.lines[n - 1].block())
            if (std::string hint = colon_hint(s.lines, n); !hint.empty()) return hint;
    return s.lines[line - 1].block() ? indent_hint(s.lines, line, column, map_value) : "";
}

}  // namespace fh
