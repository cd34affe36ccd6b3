// firsthit: the command line. Every error is caught here, once, and printed as
// one line: bad input or usage exits 2, anything else 1.
#include <cstring>
#include <iostream>

#include "cli/commands.h"
#include "core/simd.h"
#include "io/input_error.h"

namespace fh {

namespace {

const char* const kHelp =
    R"(firsthit - a fast, exact first-hit (Whitted-style) ray tracer and its movie pipeline

usage:
  firsthit render  FILE [--frame N] [--camera NAME] [--spp N] [--depth N] [--threads N] [--stats] [-o OUT.png]
  firsthit frames  MOVIE [--out DIR] [--range A:B] [--shard K/N] [--resume] [--threads N]
  firsthit bench   FILE [--frame N] [--runs K] [--threads N] [--spp N] [--depth N]
  firsthit accuracy FILE [--frame N] [--csv OUT.csv] [--plot OUT.png]
  firsthit info    FILE
  firsthit view    FILE [--frame N] [--camera NAME]
  firsthit --help | --version

commands:
  render   render one frame of a scene or movie to PNG
  frames   render the frames of a movie to a folder of PNGs (on every core)
  bench    time one frame: median ms per frame and rays per second
  accuracy what each accuracy knob costs: error against a reference vs time
  info     what a scene or movie file holds
  view     a window showing a frame: P switches cameras, arrows and Space
           scrub and play a movie, S saves the shown frame (needs GLFW)

FILE is a scene file or a movie file (a movie names its scene); see
animations/scene.yaml and animations/movie1.yaml. 'firsthit COMMAND --help'
explains a command's options.

exit status: 0 success, 2 bad input or usage (one line on stderr:
FILE:LINE:COLUMN: error: WHAT), 1 any other failure. A failed run writes no
partial image.
)";

int dispatch(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << kHelp;
        return 2;
    }
    const std::string cmd = argv[1];
    const Words words(argv + 2, argv + argc);
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        std::cout << kHelp;
        return 0;
    }
    if (cmd == "--version") {
        std::cout << "firsthit " << FIRSTHIT_VERSION << " (built for " << FIRSTHIT_ARCH << ": " << kSimdBytes
                  << "-byte SIMD, " << kLanes<double> << " doubles or " << kLanes<float> << " floats a packet)\n";
        return 0;
    }
    if (cmd == "render") return run_render(words);
    if (cmd == "frames") return run_frames(words);
    if (cmd == "bench") return run_bench(words);
    if (cmd == "info") return run_info(words);
    if (cmd == "accuracy") return run_accuracy(words);
    if (cmd == "view") return run_view(words);
    throw UsageError("unknown command '" + cmd + "'; see 'firsthit --help'");
}

}  // namespace

bool wants_help(const Words& words, const char* help) {
    for (const auto& w : words)
        if (w == "--help" || w == "-h") {
            std::cout << help;
            return true;
        }
    return false;
}

}  // namespace fh

int main(int argc, char** argv) {
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
