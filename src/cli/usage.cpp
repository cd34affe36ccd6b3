// The usage texts, generated from the flag and command tables (cli/flags.h),
// wrapped to 80 columns.
#include <sstream>

#include "cli/flags.h"

namespace fh {

namespace {

constexpr size_t kWidth = 79;
constexpr size_t kFlagColumn = 22;  // where a flag's help starts

// `text` wrapped at word boundaries; lines after the first start with
// `indent` spaces, the first continues a line already `first_used` wide.
std::string wrap(std::string_view text, size_t indent, size_t first_used) {
    std::string out;
    size_t used = first_used;
    std::istringstream words{std::string(text)};
    std::string word;
    bool line_empty = true;
    while (words >> word) {
        if (!line_empty && used + 1 + word.size() > kWidth) {
            out += "\n" + std::string(indent, ' ');
            used = indent;
            line_empty = true;
        }
        if (!line_empty) {
            out += ' ';
            ++used;
        }
        out += word;
        used += word.size();
        line_empty = false;
    }
    return out;
}

// Paragraphs apart by blank lines; one that holds line breaks is laid out
// already (a table) and kept as it is, the others are wrapped.
std::string paragraphs(std::string_view text) {
    std::string out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find("\n\n", start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view p = text.substr(start, end - start);
        out += (p.find('\n') != std::string_view::npos ? std::string(p) : wrap(p, 0, 0)) + "\n\n";
        start = end + 2;
    }
    return out;
}

std::string flag_label(const Flag& f) {
    std::string label = f.alias.empty() ? std::string(f.name) : std::string(f.alias) + ", " + std::string(f.name);
    if (!f.value.empty()) label += " " + std::string(f.value);
    return label;
}

// "  -o, --output OUT    the image to write; ...", wrapped.
std::string flag_line(const Flag& f) {
    std::string line = "  " + flag_label(f);
    if (line.size() + 1 < kFlagColumn) line += std::string(kFlagColumn - line.size(), ' ');
    else line += "\n" + std::string(kFlagColumn, ' ');
    return line + wrap(f.help, kFlagColumn, kFlagColumn) + "\n";
}

}  // namespace

std::string command_help(const CommandSpec& c) {
    std::string out = "usage: firsthit " + std::string(c.name) + " " + std::string(c.operands) +
                      (c.flags.empty() ? "" : " [options]") + "\n\n" + paragraphs(c.description);
    if (!c.flags.empty()) out += "options:\n";
    for (std::string_view name : c.flags) out += flag_line(find_flag(name));
    if (!c.flags.empty()) out += "  -h, --help          this text\n\n";
    if (!c.notes.empty()) out += paragraphs(c.notes);
    out.pop_back();  // one newline at the end, not a blank line
    return out;
}

std::string overview_help() {
    std::string out =
        "firsthit - a fast, exact first-hit (Whitted-style) ray tracer and its movie pipeline\n\nusage:\n";
    for (const CommandSpec& c : all_commands()) {
        std::string head = "  firsthit " + std::string(c.name) + " " + std::string(c.operands);
        std::string line = head;
        for (std::string_view name : c.flags) {
            const Flag& f = find_flag(name);
            const std::string item = "[" + std::string(f.alias.empty() ? f.name : f.alias) +
                                     (f.value.empty() ? "" : " " + std::string(f.value)) + "]";
            if (line.size() + 1 + item.size() > kWidth) {
                out += line + "\n";
                line = std::string(head.size(), ' ');
            }
            line += " " + item;
        }
        out += line + "\n";
    }
    out += "  firsthit [-h | --help | --version]\n\ncommands:\n";
    for (const CommandSpec& c : all_commands()) {
        std::string line = "  " + std::string(c.name);
        line += std::string(11 - line.size(), ' ');
        out += line + wrap(c.summary, 11, 11) + "\n";
    }
    out += "\noptions:\n";
    for (const Flag& f : all_flags()) out += flag_line(f);
    out += "\n" + paragraphs(
                      "FILE is a scene file or a movie file (a movie names its scene); see animations/scene.yaml "
                      "and animations/movie1.yaml, and docs/format.md for every key. 'firsthit COMMAND --help' "
                      "(or 'firsthit help COMMAND') shows a command's options only.\n\n"
                      "exit status: 0 success, 2 bad input or usage (one line on stderr: FILE:LINE:COLUMN: "
                      "error: WHAT), 1 any other failure. A failed run writes no partial image.");
    out.pop_back();
    return out;
}

}  // namespace fh
