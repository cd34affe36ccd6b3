// Every flag of `firsthit`, once, with its help text (cli/flags.h). A
// command lists the names it takes in cli/command_table.cpp.
#include <stdexcept>
#include <string>

#include "cli/flags.h"

namespace fh {

const std::vector<Flag>& all_flags() {
    static const std::vector<Flag> flags = {
        // What to render.
        {"--frame", "", "N",
         "movie files: the frame, counted from 0 (default 0); for frames: only this frame, the same as "
         "--range N-N"},
        {"--camera", "", "NAME", "scene and glTF files: the camera, by name (glTF: or index; default: the "
                                 "first listed)"},
        {"--animation", "", "A",
         "glTF files: the animation to play, by name or index, or 'all' together (default)"},
        {"--fps", "", "F", "glTF files: frames per second of their animation (default 30): frame N is N/F seconds"},
        {"--exposure", "", "X",
         "glTF files: a factor on every light's intensity, for a file too dark or bright (default 1)"},
        {"--resolution", "", "WxH",
         "render at this size instead of the file's, e.g. 160x120 for a quick preview. The image plane "
         "keeps its height, so another aspect ratio shows more or less at the sides"},
        {"--scale", "", "F",
         "render at F times the file's size, e.g. 0.25 (sides rounded, at least 1 pixel); not with "
         "--resolution"},
        // How well.
        {"--spp", "", "N", "samples per pixel (default: the file's, else 1)"},
        {"--depth", "", "N", "the longest chain of reflection rays (default: the file's, else 5)"},
        {"--precision", "", "P", "float or double: the tracer's scalar type (default double)"},
        {"--adaptive", "", "",
         "adaptive anti-aliasing: a pixel that differs from a neighbour by more than --aa-threshold is "
         "rendered again with --aa-samples samples"},
        {"--aa-threshold", "", "X", "the adaptive anti-aliasing threshold, 0..255 (default 8)"},
        {"--aa-samples", "", "N", "samples of a pixel adaptive anti-aliasing refines (default 16)"},
        {"--no-mipmaps", "", "",
         "read every texture as when magnified, at the hit, instead of over each ray's footprint from its "
         "mipmaps (faster; textures seen from afar alias)"},
        {"--no-prune", "", "",
         "debug: simulate every effect asked for, even those the effect plan proves cannot change a "
         "pixel (the same image, slower)"},
        {"--threads", "", "N", "worker threads (default: one per core)"},
        // Outputs.
        {"--output", "-o", "OUT",
         "the image to write; its extension picks the format: .png, .jpg or .jpeg (quality 95), .bmp, "
         ".tga. '-' writes PNG to standard output. Default: FILE's name with .png in the current folder "
         "(for a movie NAME_frameNNNN.png)"},
        {"--out", "", "DIR|PATTERN",
         "where the frames go: a folder (frames frame_0000.png, frame_0001.png, ...) or a file name "
         "pattern with %04d (printf's) or #### (Blender's) standing for the frame number, e.g. "
         "'shots/take1_%04d.png' (default: output/NAME, NAME the movie file's name without .yaml)"},
        {"--range", "", "R",
         "only these frames, counted from 0: A-B is A to B inclusive (as POV-Ray's +SF/+EF and Blender's "
         "-s/-e, whose frames count from 1), A:B is A to B-1 (as a Python slice), A: and A- run to the "
         "end"},
        {"--shard", "", "K/N|auto",
         "only frames i with i mod N == K (0 <= K < N), e.g. one task of a cluster job array; combines "
         "with --range. 'auto' takes it from the scheduler: a Slurm job array (SLURM_ARRAY_TASK_ID minus "
         "SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT) or a Kubernetes Indexed Job "
         "(JOB_COMPLETION_INDEX, of --shards N)"},
        {"--shards", "", "N", "the shard count for --shard auto in a Kubernetes Indexed Job (its completions)"},
        {"--resume", "", "",
         "skip frames whose file is already whole (after an interrupted or killed run: renders exactly "
         "the missing ones)"},
        {"--clean", "", "",
         "first remove the frames (and their PREFIXmovie.txt) another render left under the same names, "
         "which frames otherwise refuses to mix with this movie's; not with --resume or --shard"},
        {"--raw-video", "", "F",
         "also write every frame, in order, as raw video to file F ('-': standard output), for an "
         "encoder to read while the frames render (scripts/encode.sh --raw); not with --shard or --resume"},
        {"--raw-pix-fmt", "", "P",
         "the raw video's pixels: rgb24 (default) or yuv420p (BT.601 limited range as ffmpeg converts "
         "RGB, chroma the mean of each 2x2 block), converted on the render threads"},
        // What to print.
        {"--stats", "", "",
         "print, as key: value lines on stdout, the effect plan (what is simulated, and what is not and "
         "why), the pixels adaptive anti-aliasing refined and the rays traced by kind"},
        {"--quiet", "", "", "print nothing but errors: no progress line, warnings or summary"},
        // bench and accuracy.
        {"--runs", "", "K", "timed runs, the median reported (bench: default 7; accuracy: per setting, default 3)"},
        {"--csv", "", "OUT.csv", "write the table to this file (default: print it on stdout)"},
        {"--plot", "", "OUT.png", "plot error against time, one curve per knob (needs --csv and gnuplot)"},
        {"--reference-spp", "", "N", "samples per pixel of the reference image (default 256)"},
        {"--max-spp", "", "N", "the largest samples per pixel swept (default 64)"},
        // Everywhere.
        {"--help", "-h", "", "this text (firsthit COMMAND --help: the command's)"},
        {"--version", "", "", "the version, and the CPU and SIMD width the build targets"},
    };
    return flags;
}

const Flag& find_flag(std::string_view name) {
    for (const Flag& f : all_flags())
        if (f.name == name || (!f.alias.empty() && f.alias == name)) return f;
    throw std::logic_error("no flag " + std::string(name) + " in the flag table");
}

}  // namespace fh
