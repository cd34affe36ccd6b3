// The subcommands of `firsthit`. Each takes the words after its name and
// returns the exit status; errors are thrown and printed once, in main.
#pragma once

#include <string>
#include <vector>

namespace fh {

using Words = std::vector<std::string>;

int run_render(const Words& words);
int run_bench(const Words& words);
int run_frames(const Words& words);
int run_info(const Words& words);
int run_accuracy(const Words& words);
int run_view(const Words& words);  // src/view/view_command.cpp

extern const char* const kRenderHelp;
extern const char* const kBenchHelp;
extern const char* const kFramesHelp;
extern const char* const kInfoHelp;
extern const char* const kAccuracyHelp;
extern const char* const kViewHelp;

// Prints the command's help if words ask for it; true if it did.
bool wants_help(const Words& words, const char* help);

}  // namespace fh
