// firsthit render, info and --help through the real binary: outputs, --stats
// keys, exit statuses and the one-line errors.
#include <gtest/gtest.h>

#include "cli/run_command.h"
#include "support/png_read.h"

namespace fh::test {
namespace {

TEST(RenderCli, HelpNamesEveryCommand) {
    const auto r = run_firsthit("--help");
    EXPECT_EQ(r.status, 0);
    for (const char* word : {"render", "frames", "bench", "info", "--spp", "--shard"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
    EXPECT_EQ(run_firsthit("render --help").status, 0);
    EXPECT_NE(run_firsthit("render --help").out.find("--camera NAME"), std::string::npos);
}

// `help COMMAND` is `COMMAND --help`, as in git; a misspelt one is named.
TEST(RenderCli, HelpCommandShowsThatCommandsHelp) {
    const auto r = run_firsthit("help frames");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, run_firsthit("frames --help").out);
    EXPECT_NE(r.out.find("--out"), std::string::npos);
    const auto bad = run_firsthit("help frmaes");
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "firsthit: error: unknown command 'frmaes' (did you mean 'frames'?); see 'firsthit --help'\n");
    EXPECT_EQ(bad.out, "");
}

TEST(RenderCli, RendersBothCamerasWithStats) {
    const auto dir = fresh_dir("render_cli");
    for (const std::string cam : {"perspective", "orthographic"}) {
        const auto out = (dir / (cam + ".png")).string();
        const auto r = run_firsthit("render " + source_path("animations/scene.yaml") +
                                    " --camera " + cam + " --threads 2 --stats -o " + out);
        ASSERT_EQ(r.status, 0) << r.err;
        const Image img = read_png(out);
        EXPECT_EQ(img.width, 800);
        EXPECT_EQ(img.height, 800);
        for (const char* key : {"rays.primary: 640000\n", "rays.shadow: ", "rays.reflection: ",
                                "nonfinite_samples: 0\n", "effects: ", "render_ms: "})
            EXPECT_NE(r.out.find(key), std::string::npos) << key << " in\n" << r.out;
    }
}

TEST(RenderCli, MatchesTheCommittedReferenceRenders) {
    const auto dir = fresh_dir("render_reference");
    for (const std::string cam : {"perspective", "orthographic"}) {
        const auto out = (dir / (cam + ".png")).string();
        ASSERT_EQ(run_firsthit("render " + source_path("animations/scene.yaml") + " --camera " +
                               cam + " -o " + out)
                      .status,
                  0);
        const Image ref = read_png(source_path("tests/data/scene_" + cam + ".png"));
        ASSERT_EQ(ref.width, 800) << "reference image missing";
        const ImageDiff d = compare(read_png(out), ref);
        // Tolerance: rounding of a few pixels may move by one step across
        // compilers and CPUs; anything larger is a change in the tracer.
        EXPECT_LE(d.max_abs, 2);
        EXPECT_LT(d.differing, size_t(800 * 800 * 3 / 1000));
    }
}

TEST(RenderCli, MovieFrameRenders) {
    const auto dir = fresh_dir("render_movie");
    const auto out = (dir / "f42.png").string();
    const auto r = run_firsthit("render " + source_path("animations/movie1.yaml") +
                                " --frame 42 --stats -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("frame: 42\n"), std::string::npos);
    EXPECT_NE(r.out.find("effects: ambient diffuse specular shadows glazing\n"), std::string::npos);
    EXPECT_EQ(read_png(out).width, 800);
}

TEST(RenderCli, UsageErrorsExitTwoWithOneLine) {
    const std::string scene = source_path("animations/scene.yaml");
    struct Case {
        std::string args, message;
    } cases[] = {
        {"render " + scene + " --spx 4", "firsthit: error: unknown option '--spx' for 'render' (did you mean '--spp'?); see 'firsthit render --help'\n"},
        {"render " + scene + " --spp 0", "firsthit: error: --spp must be in [1, 4096], got 0\n"},
        {"render " + scene + " --camera persp", "firsthit: error: no camera 'persp' in " + scene + " (its cameras: 'perspective', 'orthographic')\n"},
        {"render " + scene + " --camera perspectve", "firsthit: error: no camera 'perspectve' in " + scene + " (did you mean 'perspective'?)\n"},
        {"render " + scene + " --frame 3", "firsthit: error: --frame applies to movie files; " + scene + " is a scene\n"},
        {"render " + source_path("animations/movie1.yaml") + " --frame 300", "firsthit: error: --frame must be in [0, 299], got 300\n"},
        {"render", "firsthit: error: expected one FILE (a scene or movie file), got 0\n"},
        {"paint", "firsthit: error: unknown command 'paint'; see 'firsthit --help'\n"},
    };
    for (const auto& c : cases) {
        const auto r = run_firsthit(c.args);
        EXPECT_EQ(r.status, 2) << c.args;
        EXPECT_EQ(r.err, c.message) << c.args;
    }
}

TEST(RenderCli, BadSceneFileIsOneLineWithPositionAndNoOutput) {
    const auto dir = fresh_dir("render_bad");
    const auto scene = dir / "bad.yaml";
    std::ofstream(scene) << "materials:\n  red: {color: [255, 19, 1], ambient: 0.1, diffuse: 0.5, "
                            "specular: 1.5, phong_exponent: 10}\nsurfaces:\n  - {type: sphere, "
                            "center: [0, 0, 0], radius: -1, material: red}\n";
    const auto out = dir / "out.png";
    const auto r = run_firsthit("render " + scene.string() + " -o " + out.string());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.find(scene.string() + ":4:"), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCli, UnwritableOutputIsBadInputAndLeavesNothing) {
    // Found before rendering: bad input, exit 2.
    const auto r = run_firsthit("render " + source_path("animations/scene.yaml") +
                                " -o /nonexistent-dir/x.png");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "/nonexistent-dir/x.png: error: cannot write: folder '/nonexistent-dir' does not exist\n");
    EXPECT_FALSE(std::filesystem::exists("/nonexistent-dir"));
}

TEST(RenderCli, InfoDescribesAMovie) {
    const auto r = run_firsthit("info " + source_path("animations/movie2.yaml"));
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* line : {"kind: movie\n", "frames: 300\n", "fps: 30\n", "camera: orthographic\n",
                             "lights: ambient directional spot(off)\n"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << " in\n" << r.out;
}

// info takes render's choosing flags (INTERFACE.md: render|info|bench|view
// MODEL.glb [--camera] [--frame] [--fps]) and checks them as render does.
TEST(RenderCli, InfoTakesTheFlagsThatChooseAFrame) {
    // The demo's animation is 4 s long: at 10 fps frames 0 .. 40, frame 5 at
    // 5 / 10 = 0.5 s, and the movie 41 / 10 = 4.1 s long.
    const auto g = run_firsthit("info " + source_path("animations/gltf/demo.gltf") + " --fps 10 --frame 5 --camera 0");
    ASSERT_EQ(g.status, 0) << g.err;
    EXPECT_NE(g.out.find("frames: 41\nfps: 10\nseconds: 4.1\ncamera: front\n"), std::string::npos) << g.out;
    EXPECT_NE(g.out.find("\nframe: 5\ntime: 0.5\n"), std::string::npos) << g.out;

    const auto m = run_firsthit("info " + source_path("animations/movie2.yaml") + " --frame 45");
    ASSERT_EQ(m.status, 0) << m.err;
    EXPECT_NE(m.out.find("\nframe: 45\ntime: 1.5\n"), std::string::npos) << m.out;

    const auto s = run_firsthit("info " + source_path("animations/scene.yaml") + " --camera orthographic");
    ASSERT_EQ(s.status, 0) << s.err;
    EXPECT_NE(s.out.find("kind: scene\ncamera: orthographic\nwidth: 800\nheight: 800\n"), std::string::npos) << s.out;

    const auto past = run_firsthit("info " + source_path("animations/movie2.yaml") + " --frame 300");
    EXPECT_EQ(past.status, 2);
    EXPECT_EQ(past.err, "firsthit: error: --frame must be in [0, 299], got 300\n");
    EXPECT_TRUE(past.out.empty()) << past.out;
    const auto gltf_past = run_firsthit("info " + source_path("animations/gltf/demo.gltf") + " --frame 121");
    EXPECT_EQ(gltf_past.status, 2);
    EXPECT_EQ(gltf_past.err, "firsthit: error: --frame must be in [0, 120], got 121\n");
    EXPECT_TRUE(gltf_past.out.empty()) << gltf_past.out;
    const auto scene_frame = run_firsthit("info " + source_path("animations/scene.yaml") + " --frame 2");
    EXPECT_EQ(scene_frame.status, 2);
    EXPECT_NE(scene_frame.err.find("--frame applies to movie files"), std::string::npos) << scene_frame.err;
    const auto yaml_fps = run_firsthit("info " + source_path("animations/movie2.yaml") + " --fps 10");
    EXPECT_EQ(yaml_fps.status, 2);
    EXPECT_NE(yaml_fps.err.find("--fps applies to glTF files"), std::string::npos) << yaml_fps.err;
}

}  // namespace
}  // namespace fh::test
