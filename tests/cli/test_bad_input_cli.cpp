// Every kind of bad input through the real program: exactly one line on
// stderr, `FILE:LINE:COLUMN: error: WHAT` where a position exists, exit status
// 2, nothing on stdout and no output file or folder written.
#include <gtest/gtest.h>

#include <regex>

#include "cli/run_command.h"
#include "gltf/gltf_builder.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// A good scene (64 x 64) and a good 12-frame movie of it, to break one thing at a time.
const std::string kGoodScene =
    "materials:\n"
    "  red: {color: [255, 19, 1], ambient: 0.1, diffuse: 0.5, specular: 1.5, phong_exponent: 10}\n"
    "surfaces:\n"
    "  - {type: sphere, center: [0, 0, 0], radius: 1, material: red}\n"
    "lights:\n"
    "  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.2}\n"
    "  sun: {type: directional, color: [255, 255, 255], intensity: 0.5, direction: [0, 0, -1]}\n"
    "cameras:\n"
    "  perspective: {type: perspective, width: 64, height: 64, view_point: [0, -10, 10],\n"
    "                look_at: [0, 1, -1], up: [0, 0, 1], projection_distance: 10}\n";
const std::string kGoodMovie = "scene: scene.yaml\ncamera: perspective\nfps: 12\nseconds: 1\n";

// One bad input: the files it needs (name -> content, in the case's folder;
// content "-> NAME": a symbolic link to NAME),
// the command line (DIR stands for the folder) and the one line expected.
struct Case {
    std::string name;
    std::vector<std::pair<std::string, std::string>> files;
    std::string args;
    std::string line;
};

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// Writes the case's files next to the good scene and movie, runs it, and
// checks the contract. The output (-o DIR/out.png or --out DIR/out) must not
// appear.
void check_case(const Case& c) {
    SCOPED_TRACE(c.name);
    const fs::path dir = fresh_dir("bad_" + c.name);
    std::ofstream(dir / "scene.yaml") << kGoodScene;
    std::ofstream(dir / "movie.yaml") << kGoodMovie;
    fs::create_directories(dir / "folder.yaml");
    std::ofstream(dir / "file.txt") << "x";
    for (const auto& [name, content] : c.files) {
        if (content.rfind("-> ", 0) == 0) fs::create_symlink(content.substr(3), dir / name);  // a link to a file
        else std::ofstream(dir / name, std::ios::binary) << content;
    }
    const auto before = fs::directory_iterator(dir);
    size_t entries = 0;
    for (auto it = before; it != fs::directory_iterator(); ++it) ++entries;

    const std::string args = replace_all(c.args, "DIR", dir.string());
    const auto r = run_firsthit(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.err, replace_all(c.line, "DIR", dir.string()) + "\n") << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_FALSE(fs::exists(dir / "out.png")) << args;
    EXPECT_FALSE(fs::exists(dir / "out")) << args;
    size_t after = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++after;
    }
    EXPECT_EQ(after, entries) << "a file was written: " << args;
    // ... and none replaced: the inputs keep their bytes.
    std::vector<std::pair<std::string, std::string>> files = c.files;
    files.insert(files.end(), {{"scene.yaml", kGoodScene}, {"movie.yaml", kGoodMovie}, {"file.txt", "x"}});
    for (const auto& [name, content] : files)
        if (!fs::is_symlink(dir / name) && fs::is_regular_file(dir / name)) EXPECT_EQ(slurp(dir / name), content) << name << " was replaced: " << args;
}

// A scene: the good one with `from` replaced by `to`.
std::pair<std::string, std::string> scene_with(const std::string& from, const std::string& to,
                                               const std::string& name = "bad.yaml") {
    const std::string text = replace_all(kGoodScene, from, to);
    EXPECT_NE(text, kGoodScene) << from;
    return {name, text};
}

std::string render(const std::string& file, const std::string& extra = "") {
    return "render DIR/" + file + " -o DIR/out.png" + (extra.empty() ? "" : " " + extra);
}

std::string frames(const std::string& file, const std::string& extra = "") {
    return "frames DIR/" + file + " --quiet --out DIR/out" + (extra.empty() ? "" : " " + extra);
}

TEST(BadInputCli, SceneFileMistakes) {
    const Case cases[] = {
        {"syntax", {{"bad.yaml", "surfaces: [{type: sphere\n"}}, render("bad.yaml"),
         "DIR/bad.yaml:2:1: error: invalid yaml: end of map flow not found (the '{' at line 1, column 12 is never "
         "closed)"},
        {"wrong_type", {scene_with("radius: 1", "radius: big")}, render("bad.yaml"),
         "DIR/bad.yaml:4:47: error: expected a number for 'radius', got 'big'"},
        {"missing_key", {scene_with("radius: 1, ", "")}, render("bad.yaml"),
         "DIR/bad.yaml:4:5: error: missing key 'radius' in sphere"},
        {"unknown_key", {scene_with("radius: 1", "radus: 1")}, render("bad.yaml"),
         "DIR/bad.yaml:4:39: error: unknown key 'radus' in sphere (did you mean 'radius'?)"},
        {"undefined_material", {scene_with("material: red", "material: reed")}, render("bad.yaml"),
         "DIR/bad.yaml:4:60: error: undefined material 'reed' (did you mean 'red'?)"},
        {"radius_zero", {scene_with("radius: 1", "radius: 0")}, render("bad.yaml"),
         "DIR/bad.yaml:4:47: error: 'radius' must be > 0, got 0"},
        {"radius_negative", {scene_with("radius: 1", "radius: -2")}, render("bad.yaml"),
         "DIR/bad.yaml:4:47: error: 'radius' must be > 0, got -2"},
        {"zero_normal",
         {scene_with("  - {type: sphere", "  - {type: plane, normal: [0, 0, 0], distance: 1, material: red}\n"
                                          "  - {type: sphere")},
         render("bad.yaml"), "DIR/bad.yaml:4:27: error: 'normal' must not be zero-length"},
        {"zero_direction", {scene_with("direction: [0, 0, -1]", "direction: [0, 0, 0]")}, render("bad.yaml"),
         "DIR/bad.yaml:7:79: error: 'direction' must not be zero-length"},
        {"zero_up", {scene_with("up: [0, 0, 1]", "up: [0, 0, 0]")}, render("bad.yaml"),
         "DIR/bad.yaml:10:42: error: 'up' must not be zero-length"},
        {"zero_look_at", {scene_with("look_at: [0, 1, -1]", "look_at: [0, 0, 0]")}, render("bad.yaml"),
         "DIR/bad.yaml:10:26: error: 'look_at' must not be zero-length"},
        {"nan", {scene_with("intensity: 0.2", "intensity: .nan")}, render("bad.yaml"),
         "DIR/bad.yaml:6:63: error: 'intensity' must be finite"},
        // Finite, but past what every product the tracer forms keeps finite:
        // 1e308 made every pixel NaN, a radius of 1e155 a sphere that vanished.
        {"intensity_huge", {scene_with("intensity: 0.2", "intensity: 1e308")}, render("bad.yaml"),
         "DIR/bad.yaml:6:63: error: 'intensity' must be at most 1e12, got 1e308"},
        {"radius_huge", {scene_with("radius: 1", "radius: 1e155")}, render("bad.yaml"),
         "DIR/bad.yaml:4:47: error: 'radius' must be at most 1e12, got 1e155"},
        {"inf", {scene_with("center: [0, 0, 0]", "center: [0, .inf, 0]")}, render("bad.yaml"),
         "DIR/bad.yaml:4:32: error: 'center' must be finite"},
        {"width_zero", {scene_with("width: 64", "width: 0")}, render("bad.yaml"),
         "DIR/bad.yaml:9:43: error: 'width' must be between 1 and 16384, got 0"},
        {"width_negative", {scene_with("width: 64", "width: -64")}, render("bad.yaml"),
         "DIR/bad.yaml:9:43: error: 'width' must be between 1 and 16384, got -64"},
        {"size_100000",
         {scene_with("width: 64, height: 64", "width: 100000, height: 100000")}, render("bad.yaml"),
         "DIR/bad.yaml:9:43: error: 'width' must be between 1 and 16384, got 100000"},
        {"height_over_limit", {scene_with("height: 64", "height: 16385")}, render("bad.yaml"),
         "DIR/bad.yaml:9:55: error: 'height' must be between 1 and 16384, got 16385"},
        {"spp_over_limit", {{"bad.yaml", kGoodScene + "render: {samples_per_pixel: 4097}\n"}}, render("bad.yaml"),
         "DIR/bad.yaml:11:29: error: 'samples_per_pixel' must be between 1 and 4096, got 4097"},
        {"depth_over_limit", {{"bad.yaml", kGoodScene + "render: {max_depth: 65}\n"}}, render("bad.yaml"),
         "DIR/bad.yaml:11:21: error: 'max_depth' must be between 0 and 64, got 65"},
    };
    for (const Case& c : cases) check_case(c);
}

TEST(BadInputCli, WholeFileMistakes) {
    std::string deep = "a: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
    std::string big = kGoodScene;
    while (big.size() < 20'000'000) big += "# a comment to make the file several megabytes long .........\n";
    const Case cases[] = {
        {"empty", {{"bad.yaml", ""}}, render("bad.yaml"), "DIR/bad.yaml: error: empty scene file"},
        {"binary", {{"bad.yaml", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)}}, render("bad.yaml"),
         "DIR/bad.yaml:1:1: error: not UTF-8 text: byte 0x89 (scene and movie files are UTF-8 text)"},
        {"nul_byte", {{"bad.yaml", std::string("cameras: {}\0", 12)}}, render("bad.yaml"),
         "DIR/bad.yaml:1:12: error: binary data, not text: control byte 0x00 (scene and movie files are UTF-8 text)"},
        {"deep", {{"bad.yaml", deep}}, render("bad.yaml"),
         "DIR/bad.yaml:1:67: error: maps and lists nested more than 64 levels deep"},
        {"several_mb", {{"bad.yaml", big}}, render("bad.yaml"),
         "DIR/bad.yaml: error: file too large: " + std::to_string(big.size()) +
             " bytes (the limit is 16777216 bytes, 16 MiB)"},
        {"directory", {}, render("folder.yaml"), "DIR/folder.yaml: error: cannot read file: is a folder"},
        {"missing", {}, render("nothing.yaml"), "DIR/nothing.yaml: error: cannot read file: no such file"},
        {"device", {}, "render /dev/zero -o DIR/out.png", "/dev/zero: error: cannot read file: not a regular file"},
        {"frames_of_directory", {}, frames("folder.yaml"), "DIR/folder.yaml: error: cannot read file: is a folder"},
        {"frames_of_binary", {{"bad.yaml", std::string("\0\1\2", 3)}}, frames("bad.yaml"),
         "DIR/bad.yaml:1:1: error: binary data, not text: control byte 0x00 (scene and movie files are UTF-8 text)"},
        {"frames_of_movie_with_syntax_error", {{"bad.yaml", "scene: scene.yaml\nfps: [30\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:3:1: error: invalid yaml: end of sequence flow not found (the '[' at line 2, column 6 is "
         "never closed)"},
        {"frames_of_a_scene", {}, frames("scene.yaml"),
         "firsthit: error: DIR/scene.yaml is not a movie file (a movie file has a 'scene:' key)"},
    };
    for (const Case& c : cases) check_case(c);
}

TEST(BadInputCli, MovieFileMistakes) {
    const Case cases[] = {
        {"scene_missing", {{"bad.yaml", "scene: nothing.yaml\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:1:8: error: scene file 'DIR/nothing.yaml': no such file"},
        {"scene_itself", {{"bad.yaml", "scene: bad.yaml\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:1:8: error: a movie cannot be its own scene"},
        {"scene_directory", {{"bad.yaml", "scene: folder.yaml\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:1:8: error: scene file 'DIR/folder.yaml': is a folder"},
        {"scene_is_a_movie", {{"bad.yaml", "scene: movie.yaml\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:1:8: error: scene file 'DIR/movie.yaml' is a movie, not a scene"},
        {"fps_zero", {{"bad.yaml", "scene: scene.yaml\nfps: 0\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:6: error: 'fps' must be > 0, got 0"},
        {"fps_negative", {{"bad.yaml", "scene: scene.yaml\nfps: -30\n"}}, render("bad.yaml"),
         "DIR/bad.yaml:2:6: error: 'fps' must be > 0, got -30"},
        {"seconds_zero", {{"bad.yaml", "scene: scene.yaml\nseconds: 0\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:10: error: 'seconds' must be > 0, got 0"},
        {"seconds_negative", {{"bad.yaml", "scene: scene.yaml\nseconds: -1\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:10: error: 'seconds' must be > 0, got -1"},
        {"seconds_nan", {{"bad.yaml", "scene: scene.yaml\nseconds: .nan\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:10: error: 'seconds' must be finite"},
        {"undefined_camera", {{"bad.yaml", "scene: scene.yaml\ncamera: perspectiv\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:9: error: undefined camera 'perspectiv' (did you mean 'perspective'?)"},
        {"undefined_light", {{"bad.yaml", "scene: scene.yaml\nlights: [ambient, moon]\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:19: error: undefined light 'moon'"},
        {"key_frame_huge",
         {{"bad.yaml", "scene: scene.yaml\nanimate:\n  lights.sun.intensity: {keyframes: [{frame: 99999999999999999999, value: 1}]}\n"}},
         frames("bad.yaml"), "DIR/bad.yaml:3:46: error: 'frame' must be between 0 and 2147483647, got 99999999999999999999"},
        {"intensity_path_huge", {{"bad.yaml", "scene: scene.yaml\nanimate:\n  lights.sun.intensity: 1e300\n"}},
         frames("bad.yaml"), "DIR/bad.yaml:3:3: error: lights.sun.intensity is 1e+300 at frame 0; it must be at most 1e12"},
        {"unknown_key", {{"bad.yaml", "scene: scene.yaml\nsecond: 3\n"}}, frames("bad.yaml"),
         "DIR/bad.yaml:2:1: error: unknown key 'second' in movie (did you mean 'seconds'?)"},
        {"error_in_its_scene", {scene_with("radius: 1", "radius: 0", "bad_scene.yaml"), {"bad.yaml", "scene: bad_scene.yaml\n"}},
         frames("bad.yaml"), "DIR/bad_scene.yaml:4:47: error: 'radius' must be > 0, got 0"},
        {"zero_view_direction",
         {{"bad.yaml", "scene: scene.yaml\nanimate:\n  view_point: [0, 0, 0]\n  look_at: {toward: [0, 0, 0]}\n"}},
         frames("bad.yaml"), "DIR/bad.yaml:4:3: error: camera.look_at is [0, 0, 0] at frame 0; a direction must not be zero"},
    };
    for (const Case& c : cases) check_case(c);
}

TEST(BadInputCli, OutputThatCannotBeWritten) {
    const Case cases[] = {
        {"render_missing_folder", {}, "render DIR/scene.yaml -o DIR/missing/x.png",
         "DIR/missing/x.png: error: cannot write: folder 'DIR/missing' does not exist"},
        {"render_into_a_folder", {}, "render DIR/scene.yaml -o DIR/folder.yaml",
         "DIR/folder.yaml: error: cannot write: is a folder"},
        {"render_under_a_file", {}, "render DIR/scene.yaml -o DIR/file.txt/x.png",
         "DIR/file.txt/x.png: error: cannot write: 'DIR/file.txt' is not a folder"},
        {"frames_out_is_a_file", {}, "frames DIR/movie.yaml --quiet --out DIR/file.txt",
         "DIR/file.txt: error: cannot create output folder: not a directory"},
        {"frames_out_under_a_file", {}, "frames DIR/movie.yaml --quiet --out DIR/file.txt/frames",
         "DIR/file.txt/frames: error: cannot create output folder: not a directory"},
    };
    for (const Case& c : cases) check_case(c);
}

// No output replaces a file the run reads, whatever it is called, and
// every output is checked before the work: `accuracy --csv s.yaml` once
// wrote its table over the scene it had measured, `frames --raw-video
// model.bin` truncated the model's buffer, and a bad --csv or --plot was
// found only after the sweep's minutes of rendering.
TEST(BadInputCli, OutputsThatWouldReplaceAnInputOrComeTooLateAndEmptyNames) {
    using namespace gltf_test;
    Bin bin;
    const std::string model = gltf_json(triangle_body(bin), bin, in_file("model.bin"));
    const std::string rows = "tx,ty,tz\n0,0,1\n";
    const std::string tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const auto with_instances = scene_with("surfaces:\n", "meshes:\n  tri: {file: tri.off}\nsurfaces:\n"
                                                           "  - {type: instances, mesh: tri, material: red, placements: rows.csv}\n");
    const auto with_ply = scene_with("surfaces:\n", "meshes:\n  tri: {file: tri.ply}\nsurfaces:\n"
                                                     "  - {type: instance, mesh: tri, material: red}\n");
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const std::string sweep = " --resolution 8x8 --max-spp 2 --reference-spp 2 --runs 1";
    const Case cases[] = {
        {"accuracy_csv_over_its_scene", {}, "accuracy DIR/scene.yaml --csv DIR/scene.yaml" + sweep,
         "firsthit: error: --csv DIR/scene.yaml: the table's name must end in .csv"},
        {"accuracy_csv_over_its_placements", {with_instances, {"rows.csv", rows}, {"tri.off", tri}},
         "accuracy DIR/bad.yaml --csv DIR/rows.csv" + sweep, "DIR/rows.csv: error: cannot write: it is a file this run reads"},
        {"accuracy_plot_not_png", {}, "accuracy DIR/scene.yaml --csv DIR/t.csv --plot DIR/p.xyz" + sweep,
         "firsthit: error: --plot DIR/p.xyz: the plot's name must end in .png"},
        {"accuracy_plot_without_csv", {}, "accuracy DIR/scene.yaml --plot DIR/p.png" + sweep,
         "firsthit: error: --plot needs --csv (gnuplot reads the table from it)"},
        {"accuracy_reference_below_the_sweep", {}, "accuracy DIR/scene.yaml --resolution 8x8 --max-spp 64 --reference-spp 2",
         "firsthit: error: --reference-spp 2 is below --max-spp 64: the reference must have the most samples"},
        {"accuracy_csv_missing_folder", {}, "accuracy DIR/scene.yaml --csv DIR/missing/t.csv" + sweep,
         "DIR/missing/t.csv: error: cannot write: folder 'DIR/missing' does not exist"},
        {"export_over_its_mesh", {with_ply, {"tri.ply", ply}}, "export DIR/bad.yaml -o DIR/tri.ply",
         "DIR/tri.ply: error: cannot write: it is a file this run reads"},
        {"render_over_its_scene_by_a_link", {{"link.png", "-> scene.yaml"}}, "render DIR/scene.yaml -o DIR/link.png",
         "DIR/link.png: error: cannot write: it is a file this run reads"},
        {"raw_video_over_its_buffer", {{"model.gltf", model}, {"model.bin", bin.bytes()}},
         frames("model.gltf", "--raw-video DIR/model.bin"), "DIR/model.bin: error: cannot write: it is a file this run reads"},
        {"raw_video_over_its_movie", {}, frames("movie.yaml", "--raw-video DIR/movie.yaml"),
         "DIR/movie.yaml: error: cannot write: it is a file this run reads"},
        {"raw_video_missing_folder", {}, frames("movie.yaml", "--raw-video DIR/missing/v.raw"),
         "DIR/missing/v.raw: error: cannot write: folder 'DIR/missing' does not exist"},
        {"raw_video_into_a_folder", {}, frames("movie.yaml", "--raw-video DIR/folder.yaml"),
         "DIR/folder.yaml: error: cannot write: is a folder"},
        {"mesh_file_empty", {scene_with("surfaces:\n", "meshes:\n  tri: {file: \"\"}\nsurfaces:\n")}, render("bad.yaml"),
         "DIR/bad.yaml:4:15: error: 'file' names no file (it is empty)"},
        {"placements_empty", {scene_with("surfaces:\n", "meshes:\n  tri: {file: tri.off}\nsurfaces:\n"
                                                        "  - {type: instances, mesh: tri, material: red, placements: ''}\n"),
                              {"tri.off", tri}},
         render("bad.yaml"), "DIR/bad.yaml:6:61: error: 'placements' names no file (it is empty)"},
        {"gltf_file_empty", {scene_with("surfaces:\n", "surfaces:\n  - {type: gltf, file: ''}\n")}, render("bad.yaml"),
         "DIR/bad.yaml:4:24: error: 'file' names no file (it is empty)"},
        {"gltf_exposure_past_the_flags_limit",
         {{"model.gltf", model}, {"model.bin", bin.bytes()},
          scene_with("surfaces:\n", "surfaces:\n  - {type: gltf, file: model.gltf, exposure: 1e7}\n")},
         render("bad.yaml"), "DIR/bad.yaml:4:46: error: 'exposure' must be at most 1e6 (as --exposure)"},
        {"render_empty_output", {}, "render DIR/scene.yaml -o ''",
         "firsthit: error: -o needs a file name (or '-' for standard output)"},
        {"export_empty_output", {}, "export DIR/scene.yaml -o ''",
         "firsthit: error: export needs -o OUT.ply or -o OUT.obj"},
    };
    for (const Case& c : cases) check_case(c);
}

TEST(BadInputCli, FrameSelectionsOutOfBoundsOrMalformed) {
    const Case cases[] = {
        {"range_past_end", {}, frames("movie.yaml", "--range 0:13"),
         "firsthit: error: --range 0:13: frame 12 is past the movie's end: its 12 frames are 0 to 11"},
        {"range_start_past_end", {}, frames("movie.yaml", "--range 20:30"),
         "firsthit: error: --range 20:30: frame 20 is past the movie's end: its 12 frames are 0 to 11"},
        {"range_empty", {}, frames("movie.yaml", "--range 5:3"),
         "firsthit: error: --range 5:3 is empty: A:B needs A < B (B is not rendered)"},
        {"range_no_colon", {}, frames("movie.yaml", "--range 3"),
         "firsthit: error: --range must look like A-B (frames A to B), A:B (A to B-1) or A: (A to the end), got '3'"},
        {"range_words", {}, frames("movie.yaml", "--range a:b"),
         "firsthit: error: --range start: 'a' is not a whole number >= 0"},
        {"range_negative", {}, frames("movie.yaml", "--range -1:4"),
         "firsthit: error: --range start: '-1' is not a whole number >= 0"},
        {"range_huge", {}, frames("movie.yaml", "--range 0:99999999999999999999"),
         "firsthit: error: --range end: '99999999999999999999' is more than 1000000000"},
        {"range_past_the_limit", {}, frames("movie.yaml", "--range 0:1000000001"),
         "firsthit: error: --range end: '1000000001' is more than 1000000000"},
        {"shard_n_huge", {}, frames("movie.yaml", "--shard 1/99999999999"),
         "firsthit: error: --shard N: '99999999999' is more than 1000000000"},
        {"shard_k_too_big", {}, frames("movie.yaml", "--shard 3/3"), "firsthit: error: --shard 3/3: need 0 <= K < N"},
        {"shard_zero", {}, frames("movie.yaml", "--shard 0/0"), "firsthit: error: --shard 0/0: need 0 <= K < N"},
        {"shard_no_slash", {}, frames("movie.yaml", "--shard 2"),
         "firsthit: error: --shard must look like K/N (0 <= K < N), got '2'"},
        {"shard_words", {}, frames("movie.yaml", "--shard one/two"),
         "firsthit: error: --shard K: 'one' is not a whole number >= 0"},
        {"shard_three_parts", {}, frames("movie.yaml", "--shard 1/2/3"),
         "firsthit: error: --shard N: '2/3' is not a whole number >= 0"},
        {"frame_past_end", {}, render("movie.yaml", "--frame 12"), "firsthit: error: --frame must be in [0, 11], got 12"},
        {"frame_negative", {}, render("movie.yaml", "--frame -1"), "firsthit: error: --frame must be in [0, 11], got -1"},
        {"frame_word", {}, render("movie.yaml", "--frame last"),
         "firsthit: error: --frame must be a whole number, got 'last'"},
        {"frame_huge", {}, render("movie.yaml", "--frame 99999999999999999999"),
         "firsthit: error: --frame must be a whole number, got '99999999999999999999'"},
        {"frame_of_a_scene", {}, render("scene.yaml", "--frame 1"),
         "firsthit: error: --frame applies to movie files; DIR/scene.yaml is a scene"},
        {"range_missing_value", {}, "frames DIR/movie.yaml --out DIR/out --range",
         "firsthit: error: option '--range' needs a value (R)"},
    };
    for (const Case& c : cases) check_case(c);
}

TEST(BadInputCli, QualityAndThreadFlagsOutOfBounds) {
    const Case cases[] = {
        {"spp_zero", {}, render("scene.yaml", "--spp 0"), "firsthit: error: --spp must be in [1, 4096], got 0"},
        {"spp_over", {}, render("scene.yaml", "--spp 4097"), "firsthit: error: --spp must be in [1, 4096], got 4097"},
        {"depth_over", {}, render("scene.yaml", "--depth 65"), "firsthit: error: --depth must be in [0, 64], got 65"},
        {"depth_negative", {}, frames("movie.yaml", "--depth -1"), "firsthit: error: --depth must be in [0, 64], got -1"},
        {"threads_negative", {}, frames("movie.yaml", "--threads -2"),
         "firsthit: error: --threads must be in [0, 1024], got -2"},
        {"threads_word", {}, render("scene.yaml", "--threads many"),
         "firsthit: error: --threads must be a whole number, got 'many'"},
        {"camera_unknown", {}, render("scene.yaml", "--camera perspectve"),
         "firsthit: error: no camera 'perspectve' in DIR/scene.yaml (did you mean 'perspective'?)"},
        {"precision_unknown", {}, render("scene.yaml", "--precision half"),
         "firsthit: error: --precision must be 'float' or 'double', got 'half'"},
    };
    for (const Case& c : cases) check_case(c);
}

}  // namespace
}  // namespace fh::test
