// Every flag of the command line, each declared once with its help text,
// and every command's flags, description and notes. The usage texts (the
// top-level `firsthit --help` and each `firsthit COMMAND --help`) are
// generated from these tables, and Args::parse accepts exactly the flags a
// command lists, so a flag cannot be taken but missing from the help.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fh {

struct Flag {
    std::string_view name;   // "--output"
    std::string_view alias;  // "-o", or empty
    std::string_view value;  // what it takes ("N", "WxH"), or empty for a switch
    std::string_view help;   // plain sentences; wrapped when printed
};

// A flag a user may reasonably try that the command does not take, and
// where to look instead: "--range" on render points to `frames`.
struct Pointer {
    std::string_view flag;
    std::string_view advice;
};

struct CommandSpec {
    std::string_view name;         // "render"
    std::string_view operands;     // "FILE"
    std::string_view summary;      // one line, for the top-level help
    std::string_view description;  // a paragraph under the usage line
    std::vector<std::string_view> flags;
    std::string_view notes;  // after the flags: keys, signals, file names
    std::vector<Pointer> pointers;
};

// All flags, each once (the top-level -h/--help and --version included).
const std::vector<Flag>& all_flags();
// The flag called `name` (its name or alias); std::logic_error if none is.
const Flag& find_flag(std::string_view name);

// The commands, in the order the top-level help lists them.
const std::vector<CommandSpec>& all_commands();
// The command called `name`, or nullptr.
const CommandSpec* find_command(std::string_view name);

// `firsthit COMMAND --help`: usage line, description, flags, notes.
std::string command_help(const CommandSpec& command);
// `firsthit --help`: every command with all its flags, then what each does.
std::string overview_help();

}  // namespace fh
