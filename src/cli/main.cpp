// firsthit: the command line. Every error is caught here, once, and printed as
// one line: bad input or usage exits 2, anything else 1.
#include <algorithm>
#include <cstring>
#include <map>
#include <iostream>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/flags.h"
#include "cli/huge_page_malloc.h"
#include "render/levels.h"
#include "text/input_error.h"

namespace fh {

namespace {

// The commands' entry points, by name (their flags and help: cli/flags.h).
using Run = int (*)(const Args&);
const std::map<std::string_view, Run> kRun = {
    {"render", run_render}, {"frames", run_frames}, {"bench", run_bench},
    {"accuracy", run_accuracy}, {"info", run_info}, {"export", run_export}, {"view", run_view},
};

bool asks_for_help(const Words& words) {
    return std::any_of(words.begin(), words.end(), [](const std::string& w) { return w == "--help" || w == "-h"; });
}

// The command of that name, or a usage error that names the closest one.
const CommandSpec& command_named(const std::string& name) {
    if (const CommandSpec* command = find_command(name)) return *command;
    std::vector<std::string> names;
    for (const CommandSpec& c : all_commands()) names.emplace_back(c.name);
    const std::string near = closest_match(name, names);
    throw UsageError("unknown command '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     "; see 'firsthit --help'");
}

int dispatch(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << overview_help() << "\n";
        return 2;
    }
    const std::string cmd = argv[1];
    const Words words(argv + 2, argv + argc);
    if (cmd == "help" && words.size() == 1) {  // as git's `help COMMAND`
        std::cout << command_help(command_named(words[0])) << "\n";
        return 0;
    }
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        std::cout << overview_help() << "\n";
        return 0;
    }
    // The tracer's level, chosen first: a FIRSTHIT_ISA this CPU or binary
    // cannot honour is one line before any work.
    int level = 0;
    try {
        level = level_in_use();
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (cmd == "--version") {
        const int bytes = 16 << (level - 2);  // v2: 16, v3: 32, v4: 64
        std::cout << "firsthit " << FIRSTHIT_VERSION << " (FIRSTHIT_ARCH=" << FIRSTHIT_ARCH << "; tracing at "
                  << level_name(level) << ": " << bytes << "-byte SIMD, " << bytes / 8 << " doubles or "
                  << bytes / 4 << " floats a packet)\n";
        return 0;
    }
    const CommandSpec& command = command_named(cmd);
    if (asks_for_help(words)) {
        std::cout << command_help(command) << "\n";
        return 0;
    }
    return kRun.at(command.name)(Args::parse(command, words));
}

}  // namespace

}  // namespace fh

int main(int argc, char** argv) {
    fh::use_huge_page_malloc();
    try {
        return fh::dispatch(argc, argv);
    } catch (const fh::InputError& e) {
        std::cerr << e.formatted() << "\n";
        return 2;
    } catch (const fh::UsageError& e) {
        std::cerr << "firsthit: error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "firsthit: error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "firsthit: error: " << e.what() << "\n";
        return 1;
    }
}
