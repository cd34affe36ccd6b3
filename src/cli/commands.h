// The subcommands of `firsthit`. Each takes its parsed flags (cli/args.h;
// which flags, and the help texts: cli/flags.h) and returns the exit status;
// errors are thrown and printed once, in main.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"

namespace fh {

using Words = std::vector<std::string>;

int run_render(const Args& args);
int run_bench(const Args& args);
int run_frames(const Args& args);
int run_info(const Args& args);
int run_accuracy(const Args& args);
int run_export(const Args& args);
int run_view(const Args& args);  // src/view/view_command.cpp

}  // namespace fh
