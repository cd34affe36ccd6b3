// The commands of `firsthit`: what each does, the flags it takes (by name,
// from cli/flag_table.cpp) and the notes under its flags (cli/flags.h).
#include "cli/flags.h"

namespace fh {

namespace {

constexpr std::string_view kSizeAdvice = "set the image size with --resolution WxH (e.g. 160x120) or --scale F";

// The pointers every rendering command shares: the size flags people try.
std::vector<Pointer> size_pointers(std::vector<Pointer> more = {}) {
    for (const char* f : {"--width", "--height", "--size", "--res", "-w"}) more.push_back({f, kSizeAdvice});
    return more;
}

}  // namespace

const std::vector<CommandSpec>& all_commands() {
    static const std::vector<CommandSpec> commands = {
        {"render", "FILE", "render one frame of a scene or movie to an image",
         "Renders one frame of a scene or movie file (a movie names its scene) to an image, and prints "
         "the path it wrote.",
         {"--frame", "--camera", "--animation", "--fps", "--exposure", "--resolution", "--scale", "--spp", "--depth",
          "--precision", "--adaptive", "--aa-threshold", "--aa-samples", "--no-mipmaps", "--no-prune", "--threads", "--output",
          "--stats", "--quiet"},
         "The image is written under a temporary name and renamed: it is whole or absent.",
         size_pointers({{"--range", "render draws one frame; for several use 'firsthit frames MOVIE --range A-B'"},
                        {"--out", "render writes one image with -o FILE; 'firsthit frames MOVIE --out DIR' "
                                  "writes a movie's frames"}})},
        {"frames", "MOVIE", "render a movie's frames to PNG files, on every core",
         "Renders the frames of a movie file to DIR/frame_0000.png, frame_0001.png, ... (or the --out "
         "pattern's names), and beside them PREFIXmovie.txt (frame_movie.txt beside frame_NNNN.png): "
         "the movie, its frame count, fps and size, which scripts/encode.sh reads. Each file is written under "
         "a temporary name and renamed, so a frame file is always whole. On a terminal a progress line "
         "shows frames done, frames per second and the time left.",
         {"--out", "--frame", "--range", "--shard", "--shards", "--resume", "--clean", "--camera", "--animation",
          "--fps", "--exposure", "--resolution", "--scale",
          "--spp", "--depth", "--precision", "--adaptive", "--aa-threshold", "--aa-samples", "--no-mipmaps", "--no-prune",
          "--threads", "--raw-video", "--raw-pix-fmt", "--stats", "--quiet"},
         "Frames of another movie or size under the same names (an earlier, longer or larger render into "
         "the same folder) are refused rather than mixed in: pass --clean to remove them, or another "
         "--out.\n\n"
         "SIGINT or SIGTERM (Ctrl-C): no new frames are started, the frames in flight are finished if "
         "they take less than half a second more (else abandoned), and the run exits with 128 + the "
         "signal's number; run it again with --resume. A killed run leaves only whole frames; "
         "temporaries (frame_NNNN.png.tmp-...) of dead runs are removed by the next run.",
         size_pointers({{"--output", "frames writes many files: --out DIR, or --out 'DIR/name_%04d.png'"},
                        {"-o", "frames writes many files: --out DIR, or --out 'DIR/name_%04d.png'"},
                       })},
        {"bench", "FILE", "time one frame: median ms per frame and rays per second",
         "Renders one frame several times after a warm-up run and prints, as key: value lines, the median "
         "time per frame (rendering only, no image written), rays per second and the rays traced by kind; "
         "and, apart, the time to load the file (load_ms) and to prepare the scene once for all frames "
         "(prepare_ms: flattening it for the tracer and building its BVH, of which build_ms the BVH; "
         "bvh_nodes its size).",
         {"--frame", "--camera", "--animation", "--fps", "--exposure", "--resolution", "--scale", "--runs",
          "--threads", "--spp", "--depth", "--precision", "--adaptive", "--aa-threshold", "--aa-samples",
          "--no-mipmaps", "--no-prune"},
         "",
         size_pointers()},
        {"accuracy", "FILE", "what each accuracy knob costs: error against a reference vs time",
         "Measures what each accuracy knob costs: renders a reference (double precision, --reference-spp "
         "samples per pixel, glazing depth 16, deeper if 16 has not converged), then sweeps samples per "
         "pixel 1..--max-spp (uniform and adaptive), depth 0..8, float against double and, where a "
         "texture may be seen from afar, its mipmaps against none (--no-mipmaps), and prints a table "
         "(CSV) with a row per setting.",
         {"--frame", "--camera", "--resolution", "--scale", "--csv", "--plot", "--runs", "--threads",
          "--reference-spp", "--max-spp", "--aa-threshold"},
         "The table's columns:\n"
         "  setting         what the row measures: reference (the first row), spp (uniform samples\n"
         "                  per pixel), adaptive, depth, precision or mipmaps\n"
         "  spp             samples per pixel; in adaptive rows the samples of a refined pixel\n"
         "  adaptive        1 if adaptive anti-aliasing is on (1 sample a pixel, then spp samples\n"
         "                  for the refined ones)\n"
         "  depth           the longest chain of reflection rays\n"
         "  precision       float or double\n"
         "  ms              the median render time of --runs runs, in milliseconds\n"
         "  rays            the rays one render traced, all kinds\n"
         "  rmse            root mean square error against the reference, in 0..255 levels\n"
         "  psnr            peak signal-to-noise ratio, 20 log10(255 / rmse) dB: higher is better,\n"
         "                  inf means identical\n"
         "  max_error       the largest difference of one channel of one pixel, 0..255\n"
         "  refined_pixels  the pixels adaptive anti-aliasing rendered again (0 in other rows)\n"
         "  isolated_rmse   depth and precision rows: rmse against a one-sample reference (double,\n"
         "                  the reference's depth), so the knob's own error is not hidden under\n"
         "                  one sample's aliasing; other rows: the same as rmse\n"
         "  isolated_psnr   the same as a psnr\n"
         "  mipmaps         1 if textures seen from afar are read from their mipmaps over each\n"
         "                  ray's footprint (the default), 0 if read as magnified (--no-mipmaps);\n"
         "                  the two mipmaps rows take one sample a pixel\n\n"
         "Which setting for which purpose: previews --spp 1, with --scale 0.25 for speed; final frames "
         "--adaptive (the quality of uniform --aa-samples for a fraction of their time, as psnr against "
         "ms shows); --depth the smallest whose isolated_psnr is inf or above about 50 dB; --precision "
         "float where its isolated_psnr is that high and its ms lower; --no-mipmaps only where its psnr "
         "stays as high.",
         size_pointers()},
        {"info", "FILE", "what a scene, movie or glTF file holds",
         "Prints what a scene, movie or glTF file holds, as key: value lines: for a movie its frame count, "
         "fps, seconds, camera and image size; for a scene its surfaces, lights and cameras. The flags "
         "choose as render's do, and are checked as render checks them: --frame adds the frame and its "
         "time, --camera the camera chosen.",
         {"--frame", "--camera", "--animation", "--fps", "--exposure"},
         "",
         {}},
        {"export", "FILE", "a frame's triangles in world space to a .ply or .obj file",
         "Writes the triangles a frame of a scene, movie or glTF file shows -- its own and each instance's, "
         "after groups, hierarchy and animation -- in world space to a PLY (binary, double coordinates) or "
         "OBJ file, each triangle with its own three vertices, so any mesh viewer can check a scene or an "
         "animation. Spheres, disks and planes are not triangles and are left out (with a warning).",
         {"--frame", "--animation", "--fps", "--output", "--quiet"},
         "The file is written under a temporary name and renamed: it is whole or absent.",
         {{"--out", "export writes one file: -o OUT.ply or -o OUT.obj"}}},
        {"view", "FILE", "a window showing a frame (needs GLFW)",
         "Opens a window showing a frame of a scene or movie file, rendered at a quarter of the resolution "
         "at once, then at full resolution (the same image as 'firsthit render' gives).",
         {"--frame", "--camera", "--animation", "--fps", "--exposure", "--resolution", "--scale", "--spp", "--depth",
          "--precision", "--adaptive", "--aa-threshold", "--aa-samples", "--no-mipmaps", "--no-prune", "--threads"},
         "keys:\n"
         "  P             switch camera projection: a scene file shows its next camera with the other\n"
         "                projection (orthographic <-> perspective); a movie keeps its camera path\n"
         "                and flips the projection\n"
         "  Left / Right  previous / next frame (movies)\n"
         "  Home / End    first / last frame (movies)\n"
         "  Space         play / pause at the movie's fps (looping); frames follow the clock, the\n"
         "                resolution drops while rendering cannot keep up\n"
         "  S             save the shown frame at full resolution as view_STEM[_frameNNNN]_CAMERA.png\n"
         "                in the current folder (pauses playback); prints the path on stdout\n"
         "  Q, Esc        quit\n\n"
         "The title shows the file, frame, camera, image size and ms per frame. Needs a display (X11 or "
         "Wayland); without one, exits 1 with one line. Needs firsthit built with GLFW and OpenGL "
         "(apt-get install libglfw3-dev libgl-dev).",
         size_pointers()},
    };
    return commands;
}

const CommandSpec* find_command(std::string_view name) {
    for (const CommandSpec& c : all_commands())
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace fh
