// The documentation a reader follows: README.md and docs/*.md.
//
// Links: every relative link and image, [text](target) or ![alt](target),
// names a file or folder that exists, relative to the markdown file's folder
// (a #fragment is cut off; web and mail links and pure #anchors are not
// checked; links inside code are not links). The README stays at most 250
// lines: the depth belongs in docs/.
//
// Commands: every `firsthit ...` line of a shell code block (```sh, ```bash,
// ```console, ```shell or a plain ```) is one the command-line parser
// accepts, so the docs never show a flag that does not exist or that the
// command does not take. A line counts when, after an optional "$ " prompt,
// NAME=value environment prefixes and a "build/" or "./build/" before the
// program, its first word is `firsthit`. Its words are split as a shell
// would, honouring single and double quotes and backslashes; the command
// ends at an unquoted `|`, `;`, `&`, `>` (with a `2` before it) or a `#`
// that starts a word. The flags' values are not checked (the commands check
// them when they run), only that Args::parse takes the words.
//
// A line is a template rather than an example, and is skipped, when a word
// holds a placeholder: `<...>` (also an input redirection), `$` (a variable
// or `$(...)`), `...` or `…`, `[` (an optional part, as in the synopsis), or
// only uppercase letters among its letters (FILE, MOVIE, DIR, N, K/N). So
// that most commands are checked, the docs use real example paths.
// `firsthit --help`, `-h` and `--version`, and any command with --help among
// its words, are accepted as they are (main answers them before parsing).
// An unknown command name is a failure: it is a typo in the docs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/flags.h"
#include "cli/run_command.h"
#include "text/input_error.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// README.md, then docs/*.md in name order.
std::vector<fs::path> markdown_files() {
    std::vector<fs::path> files{fs::path(source_path("README.md"))};
    std::vector<fs::path> docs;
    for (const fs::directory_entry& e : fs::directory_iterator(source_path("docs")))
        if (e.is_regular_file() && e.path().extension() == ".md") docs.push_back(e.path());
    std::sort(docs.begin(), docs.end());
    files.insert(files.end(), docs.begin(), docs.end());
    return files;
}

// "docs/cli.md" for messages.
std::string shown(const fs::path& file) {
    return fs::path(file).lexically_relative(fs::path(FIRSTHIT_SOURCE_DIR)).generic_string();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = std::min(text.find('\n', at), text.size());
        lines.push_back(text.substr(at, end - at));
        at = end + 1;
    }
    return lines;
}

std::string trim_left(const std::string& s) {
    const size_t first = s.find_first_not_of(" \t");
    return first == std::string::npos ? "" : s.substr(first);
}

// A markdown file's text outside fenced code blocks, with inline code spans
// blanked out; newlines are kept, so positions still give line numbers.
std::string prose(const std::string& markdown) {
    std::string out;
    bool fenced = false;
    for (const std::string& line : lines_of(markdown)) {
        const bool fence = trim_left(line).starts_with("```");
        if (fence) fenced = !fenced;
        out += (fence || fenced) ? std::string() : line;
        out += '\n';
    }
    // A code span: a run of n backticks up to the next run of exactly n.
    for (size_t i = 0; i < out.size();) {
        if (out[i] != '`') {
            ++i;
            continue;
        }
        size_t n = 0;
        while (i + n < out.size() && out[i + n] == '`') ++n;
        const std::string run(n, '`');
        size_t close = out.find(run, i + n);
        while (close != std::string::npos && close + n < out.size() && out[close + n] == '`')
            close = out.find(run, close + n + 1);
        if (close == std::string::npos) {
            i += n;
            continue;
        }
        for (size_t k = i; k < close + n; ++k)
            if (out[k] != '\n') out[k] = ' ';
        i = close + n;
    }
    return out;
}

size_t line_at(const std::string& text, size_t position) {
    const auto end = text.begin() + static_cast<std::ptrdiff_t>(position);
    return 1 + static_cast<size_t>(std::count(text.begin(), end, '\n'));
}

TEST(Docs, EveryRelativeLinkAndImageResolves) {
    const std::regex link(R"(\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))");
    size_t checked = 0;
    for (const fs::path& file : markdown_files()) {
        const std::string text = prose(slurp(file));
        for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
            std::string target = (*it)[1];
            if (target.starts_with("#") || target.starts_with("http://") || target.starts_with("https://") ||
                target.starts_with("mailto:"))
                continue;
            target = target.substr(0, target.find('#'));
            ++checked;
            EXPECT_TRUE(fs::exists(file.parent_path() / target))
                << shown(file) << ":" << line_at(text, static_cast<size_t>(it->position())) << ": the link '"
                << (*it)[1] << "' names nothing";
        }
    }
    EXPECT_GE(checked, 20u) << "too few links found: is the link pattern still right?";
}

TEST(Docs, TheReadmeIsShort) {
    const size_t lines = lines_of(slurp(source_path("README.md"))).size();
    EXPECT_LE(lines, 250u) << "README.md has " << lines << " lines; move the depth into docs/";
}

// The words of a shell command line, as described atop this file; nullopt
// when the line is a template (a placeholder in it) or its quotes do not
// close.
std::optional<std::vector<std::string>> shell_words(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    char quote = 0;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quote != 0) {
            if (c == quote) quote = 0;
            else word += c;
            continue;
        }
        if (c == '\'' || c == '"') {
            quote = c;
            in_word = true;
        } else if (c == ' ' || c == '\t') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
        } else if (c == '#' && !in_word) {
            break;  // a comment
        } else if (c == '|' || c == ';' || c == '&' || c == '>') {
            // The command ends: a pipe, a list or a redirection ("2>": the 2 is not a word).
            const bool fd = c == '>' && in_word && !word.empty() &&
                            std::all_of(word.begin(), word.end(), [](char d) { return d >= '0' && d <= '9'; });
            if (in_word && !fd) words.push_back(word);
            in_word = false;
            break;
        } else if (c == '<') {
            return std::nullopt;
        } else if (c == '\\' && i + 1 < line.size()) {
            word += line[++i];
            in_word = true;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (quote != 0) return std::nullopt;
    if (in_word) words.push_back(word);
    return words;
}

bool is_placeholder(const std::string& word) {
    if (word.find('$') != std::string::npos || word.find("...") != std::string::npos ||
        word.find("\u2026") != std::string::npos || word.find('[') != std::string::npos)
        return true;
    bool letters = false;
    for (const char c : word) {
        if (std::islower(static_cast<unsigned char>(c))) return false;
        if (std::isupper(static_cast<unsigned char>(c))) letters = true;
    }
    return letters;
}

struct ShownCommand {
    fs::path file;
    size_t line = 0;
    std::string text;
};

// The lines of shell code blocks that run firsthit, continuation lines
// (ending in a backslash) joined.
std::vector<ShownCommand> shown_commands() {
    static const std::vector<std::string> shells = {"", "sh", "bash", "console", "shell"};
    std::vector<ShownCommand> commands;
    for (const fs::path& file : markdown_files()) {
        const std::vector<std::string> lines = lines_of(slurp(file));
        bool fenced = false, shell = false;
        for (size_t i = 0; i < lines.size(); ++i) {
            const std::string line = trim_left(lines[i]);
            if (line.starts_with("```")) {
                fenced = !fenced;
                std::string info = line.substr(3);
                info = info.substr(0, info.find_first_of(" \t{"));
                shell = fenced && std::find(shells.begin(), shells.end(), info) != shells.end();
                continue;
            }
            if (!fenced || !shell) continue;
            const size_t number = i + 1;
            std::string command = line;
            while (!command.empty() && command.back() == '\\' && i + 1 < lines.size())
                command = command.substr(0, command.size() - 1) + " " + trim_left(lines[++i]);
            if (command.starts_with("$ ")) command = trim_left(command.substr(2));
            static const std::regex environment(R"(^[A-Za-z_][A-Za-z0-9_]*=\S*\s+)");
            for (std::smatch m; std::regex_search(command, m, environment);) command = m.suffix().str();
            for (const char* dir : {"./build/", "build/"})
                if (command.starts_with(dir)) command = command.substr(std::string(dir).size());
            if (command.starts_with("firsthit ") || command == "firsthit")
                commands.push_back({file, number, command});
        }
    }
    return commands;
}

TEST(Docs, EveryFirsthitCommandShownIsAcceptedByTheParser) {
    size_t checked = 0;
    for (const ShownCommand& shown_command : shown_commands()) {
        const std::string where = shown(shown_command.file) + ":" + std::to_string(shown_command.line) + ": ";
        const std::optional<std::vector<std::string>> words = shell_words(shown_command.text);
        if (!words || words->size() < 2) continue;
        if (std::any_of(words->begin() + 1, words->end(), is_placeholder)) continue;
        const std::string& name = (*words)[1];
        const std::vector<std::string> rest(words->begin() + 2, words->end());
        if (name == "--help" || name == "-h" || name == "--version") {
            EXPECT_TRUE(rest.empty()) << where << shown_command.text;
            continue;
        }
        const CommandSpec* command = find_command(name);
        if (command == nullptr) {
            ADD_FAILURE() << where << "'" << name << "' is not a command: " << shown_command.text;
            continue;
        }
        ++checked;
        if (std::find(rest.begin(), rest.end(), "--help") != rest.end() ||
            std::find(rest.begin(), rest.end(), "-h") != rest.end())
            continue;
        try {
            Args::parse(*command, rest);
        } catch (const UsageError& e) {
            ADD_FAILURE() << where << e.what() << "\n  in: " << shown_command.text;
        } catch (const InputError& e) {
            ADD_FAILURE() << where << e.formatted() << "\n  in: " << shown_command.text;
        } catch (const std::exception& e) {
            ADD_FAILURE() << where << e.what() << "\n  in: " << shown_command.text;
        }
    }
    EXPECT_GE(checked, 10u) << "too few firsthit commands found in the docs' code blocks";
}

// The splitter itself, on the shapes the docs use.
TEST(Docs, ShellWordsSplitLikeAShell) {
    using Words = std::vector<std::string>;
    auto split = [](const std::string& line) { return shell_words(line).value_or(Words{"(template)"}); };
    EXPECT_EQ(split("firsthit frames m.yaml --out 'shots/take 1_%04d.png' # a comment"),
              (Words{"firsthit", "frames", "m.yaml", "--out", "shots/take 1_%04d.png"}));
    EXPECT_EQ(split("firsthit render m.yaml -o - | display"), (Words{"firsthit", "render", "m.yaml", "-o", "-"}));
    EXPECT_EQ(split("firsthit render m.yaml -o - > f.png"), (Words{"firsthit", "render", "m.yaml", "-o", "-"}));
    EXPECT_EQ(split("firsthit info m.yaml 2>/dev/null && echo ok"), (Words{"firsthit", "info", "m.yaml"}));
    EXPECT_EQ(split("firsthit render \"my scene.yaml\"#x"), (Words{"firsthit", "render", "my scene.yaml#x"}));
    EXPECT_EQ(split("firsthit render <FILE>"), Words{"(template)"});
    EXPECT_EQ(split("firsthit render 'open"), Words{"(template)"});
    EXPECT_TRUE(is_placeholder("FILE"));
    EXPECT_TRUE(is_placeholder("K/N"));
    EXPECT_TRUE(is_placeholder("[--frame"));
    EXPECT_TRUE(is_placeholder("$(nproc)"));
    EXPECT_FALSE(is_placeholder("160x120"));
    EXPECT_FALSE(is_placeholder("animations/movie1.yaml"));
    EXPECT_FALSE(is_placeholder("--out"));
    EXPECT_FALSE(is_placeholder("0/4"));
}

}  // namespace
}  // namespace fh::test
