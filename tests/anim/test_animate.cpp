// Animating anything: each path kind by hand, keys in seconds or frames,
// every animatable property changing the rendered frame exactly as the same
// value written into the scene does, the effect plan per frame, and each
// mistake one line naming the path and the frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "anim/movie.h"
#include "cli/run_command.h"
#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "pipeline/job.h"
#include "render/prepared_scene.h"
#include "test_util.h"

namespace fh {
namespace {

namespace fs = std::filesystem;
using test::write_temp_file;

// Keys 0 at frame 0 and 8 at frame 4; frame 1 is t = 1/4 of the way.
double value_at(Interpolation i, int frame) {
    const Keyframes k{{{0, dvec3(0)}, {4, dvec3(8)}}, i};
    return evaluate(Path(k), frame, 10, dvec3(0)).x;
}

TEST(Animate, EachInterpolationByHand) {
    EXPECT_EQ(value_at(Interpolation::step, 1), 0);
    EXPECT_EQ(value_at(Interpolation::step, 3), 0);
    EXPECT_EQ(value_at(Interpolation::linear, 1), 2);
    EXPECT_EQ(value_at(Interpolation::ease_in, 1), 0.5);        // 8 (1/4)^2
    EXPECT_EQ(value_at(Interpolation::ease_out, 1), 3.5);       // 8 (1 - (3/4)^2)
    EXPECT_EQ(value_at(Interpolation::ease_in_out, 1), 1.25);   // 8 (3/16 - 2/64)
    EXPECT_EQ(value_at(Interpolation::ease_in_out, 2), 4);      // the middle
    for (const Interpolation i : {Interpolation::step, Interpolation::linear, Interpolation::catmull_rom,
                                  Interpolation::ease_in, Interpolation::ease_out, Interpolation::ease_in_out}) {
        EXPECT_EQ(value_at(i, 0), 0);  // at the keys exactly
        EXPECT_EQ(value_at(i, 4), 8);
        EXPECT_EQ(value_at(i, 9), 8);  // the last key holds after it
    }
    // On vectors, component by component.
    const Keyframes v{{{2, dvec3(0, 4, -8)}, {6, dvec3(4, 0, 8)}}, Interpolation::ease_out};
    EXPECT_EQ(evaluate(Path(v), 0, 10, dvec3(0)), dvec3(0, 4, -8));  // before the first key: held
    EXPECT_EQ(evaluate(Path(v), 4, 10, dvec3(0)), dvec3(3, 1, 4));    // t = 1/2: weight 3/4
}

// A scene with named things, 24 x 24, and a movie over it.
const std::string kAnimateScene =
    "materials:\n"
    "  red: {color: [255, 19, 1], ambient: 0.1, diffuse: 0.5, specular: 1.5, phong_exponent: 10}\n"
    "  teal: {color: [20, 255, 255], ambient: 0.1, diffuse: 0.3, specular: 10, phong_exponent: 100,"
    " glazed: true, reflectivity: 0.3}\n"
    "surfaces:\n"
    "  - {type: sphere, name: ball, center: [-1, 0, 0], radius: 1, material: red}\n"
    "  - {type: sphere, center: [1.5, 0, 0.5], radius: 1.2, material: teal}\n"
    "  - {type: plane, name: floor, normal: [0, 0, 1], distance: -1, material: teal}\n"
    "  - {type: triangle, name: tri, vertices: [[-3, 3, 0], [-1, 3, 0], [-2, 4, 2]], material: red}\n"
    "lights:\n"
    "  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.002}\n"
    "  sun: {type: directional, color: [255, 255, 230], intensity: 0.02, direction: [-50, 50, -50]}\n"
    "  spot: {type: spot, color: [255, 255, 255], intensity: 2.2, position: [0, 0, 10], direction: [0, 0, -1],"
    " max_angle: 6.283185307179586}\n"
    "cameras:\n"
    "  eye: {type: perspective, width: 24, height: 24, view_point: [2, -10, 10], look_at: [0, 2, -1],"
    " up: [0, 0, 1], projection_distance: 10}\n";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

// Frame `frame` of the movie in `dir`, rendered by the movie pipeline.
std::string frame_bytes(const fs::path& dir, const std::string& movie, int frame = 0) {
    const fs::path out = dir / ("out_" + movie + std::to_string(frame));
    const auto r = test::run_firsthit("frames " + (dir / movie).string() + " --quiet --range " + std::to_string(frame) +
                                      ":" + std::to_string(frame + 1) + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    std::ifstream f(out / ("frame_" + std::string(4 - std::to_string(frame).size(), '0') + std::to_string(frame) + ".png"),
                    std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

struct PropertyCase {
    std::string path, value;      // animate: PATH: VALUE
    std::string from, to;         // the same value written into the scene by hand
    std::string movie_lights = "[ambient, spot]";
    std::string expected_lights = "[ambient, spot]";
};

TEST(Animate, EveryPropertyChangesTheFrameAsTheSceneFileWould) {
    const std::vector<PropertyCase> cases = {
        {"surfaces.ball.center", "[-1, 0, 1]", "center: [-1, 0, 0]", "center: [-1, 0, 1]"},
        {"surfaces.ball.radius", "0.5", "radius: 1, material: red", "radius: 0.5, material: red"},
        {"surfaces.floor.distance", "-1.5", "distance: -1", "distance: -1.5"},
        {"surfaces.floor.normal", "[0, 0.2, 1]", "normal: [0, 0, 1], distance: -1",
         "normal: [0, 0.19611613513818404, 0.98058067569092022], distance: -1"},
        {"surfaces.tri.transform.translate", "[0, 0, 1]", "[[-3, 3, 0], [-1, 3, 0], [-2, 4, 2]]",
         "[[-3, 3, 1], [-1, 3, 1], [-2, 4, 3]]"},
        {"lights.spot.intensity", "1.1", "intensity: 2.2", "intensity: 1.1"},
        {"lights.spot.position", "[1, 0, 10]", "position: [0, 0, 10]", "position: [1, 0, 10]"},
        {"lights.spot.direction", "[0, 0.5, -1]", "direction: [0, 0, -1]", "direction: [0, 0.5, -1]"},
        {"lights.spot.max_angle", "0.3", "max_angle: 6.283185307179586", "max_angle: 0.3"},
        {"lights.spot.color", "[255, 0, 0]", "color: [255, 255, 255], intensity: 2.2",
         "color: [255, 0, 0], intensity: 2.2"},
        {"lights.sun.on", "true", "", "", "[ambient, spot]", "[ambient, spot, sun]"},
        {"materials.red.color", "[0, 19, 255]", "color: [255, 19, 1]", "color: [0, 19, 255]"},
        {"materials.teal.reflectivity", "0.9", "reflectivity: 0.3", "reflectivity: 0.9"},
        {"materials.red.diffuse", "0.9", "diffuse: 0.5, specular: 1.5", "diffuse: 0.9, specular: 1.5"},
        {"camera.projection_distance", "5", "projection_distance: 10", "projection_distance: 5"},
        {"camera.view_point", "[3, -10, 10]", "view_point: [2, -10, 10]", "view_point: [3, -10, 10]"},
    };
    const fs::path dir = fs::path(write_temp_file("animate_all/scene.yaml", kAnimateScene)).parent_path();
    write_temp_file("animate_all/base.yaml", "scene: scene.yaml\nlights: [ambient, spot]\nseconds: 0.1\n");
    const std::string base = frame_bytes(dir, "base.yaml");
    for (const PropertyCase& c : cases) {
        const std::string name = c.path;
        write_temp_file("animate_all/" + name + ".movie.yaml", "scene: scene.yaml\nlights: " + c.movie_lights +
                        "\nseconds: 0.1\nanimate:\n  " + c.path + ": " + c.value + "\n");
        write_temp_file("animate_all/" + name + ".scene.yaml", c.from.empty() ? kAnimateScene : replaced(kAnimateScene, c.from, c.to));
        write_temp_file("animate_all/" + name + ".expected.yaml", "scene: " + name + ".scene.yaml\nlights: " +
                        c.expected_lights + "\nseconds: 0.1\n");
        const std::string animated = frame_bytes(dir, name + ".movie.yaml");
        EXPECT_EQ(animated, frame_bytes(dir, name + ".expected.yaml")) << c.path;
        EXPECT_NE(animated, base) << c.path << " changed nothing";
    }
}

TEST(Animate, TimeAndFrameKeysAgreeAtTheKeys) {
    write_temp_file("animate_time/scene.yaml", kAnimateScene);
    const Movie m = load_movie(write_temp_file("animate_time/m.yaml",
        "scene: scene.yaml\nfps: 24\nseconds: 2\nanimate:\n"
        "  surfaces.ball.radius: {keyframes: [{time: 0, value: 1}, {time: 0.5, value: 2}, {frame: 36, value: 0.5},"
        " {time: 2, value: 1}]}\n"));
    Target radius = m.animations.at(0).target;
    EXPECT_EQ(value_at(m, radius, 12).x, 2);   // time 0.5 = frame 12
    EXPECT_EQ(value_at(m, radius, 36).x, 0.5);
    EXPECT_EQ(value_at(m, radius, 6).x, 1.5);  // halfway to the time key
    EXPECT_EQ(value_at(m, radius, 47).x, 0.5 + 0.5 * 11 / 12);
    // A key at the movie's end (time 2 = frame 48) is inside the movie.
    const std::string path = write_temp_file("animate_time/late.yaml",
        "scene: scene.yaml\nfps: 24\nseconds: 2\nanimate:\n  surfaces.ball.radius: {keyframes: [{time: 2.5, value: 1}]}\n");
    try {
        load_movie(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), path + ":5:45: error: keyframe at time 2.5 s (frame 60) is past the movie's end "
                                        "(frame 48, 2 s)");
    }
    // Where fps x seconds is no whole number the end is `seconds` itself:
    // 3 fps for 1.1 s is frames 0..2 and a key at time 1.1 (frame 3.3) is
    // its end (it was refused as past frame 3); rounding in a time is no
    // step past it.
    const Movie odd = load_movie(write_temp_file("animate_time/odd.yaml",
        "scene: scene.yaml\nfps: 3\nseconds: 1.1\nanimate:\n  surfaces.ball.radius: {keyframes: [{frame: 0, value: 1},"
        " {time: 1.1, value: 2}]}\n"));
    EXPECT_NEAR(value_at(odd, odd.animations.at(0).target, 2).x, 1 + 2 / 3.3, 1e-12);
    EXPECT_NO_THROW(load_movie(write_temp_file("animate_time/rounded.yaml",
        "scene: scene.yaml\nfps: 24\nseconds: 2\nanimate:\n  surfaces.ball.radius: {keyframes: [{time: 2.0000001, value: 1}]}\n")));
}

TEST(Animate, FollowingAndAimingAtMovingThings) {
    write_temp_file("animate_follow/scene.yaml", kAnimateScene);
    const Movie m = load_movie(write_temp_file("animate_follow/m.yaml",
        "scene: scene.yaml\nfps: 4\nseconds: 1\nanimate:\n"
        "  surfaces.ball.center: {keyframes: [{frame: 0, value: [0, 0, 0]}, {frame: 4, value: [4, 0, 0]}]}\n"
        "  camera.view_point: [0, -10, 0]\n"
        "  camera.look_at: {toward: surfaces.ball}\n"
        "  lights.spot.direction: {toward: {keyframes: [{frame: 0, value: [0, 0, 0]}, {frame: 2, value: [10, 0, 10]}]}}\n"));
    // Frame 2: the ball at (2,0,0), seen from (0,-10,0).
    const Camera cam = camera_at(m, 2);
    EXPECT_NEAR(cam.look_at.x, 2 / std::sqrt(104.0), 1e-15);
    EXPECT_NEAR(cam.look_at.y, 10 / std::sqrt(104.0), 1e-15);
    // The spot at (0,0,10) aims at (5,0,5) at frame 1: (5,0,-5) normalised.
    Scene s = m.scene;
    scene_at(m, 1, s);
    EXPECT_NEAR(s.spot_lights[0].axis.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(s.spot_lights[0].axis.z, -std::sqrt(0.5), 1e-15);
    EXPECT_EQ(s.spheres()[0].center, dvec3(1, 0, 0));
}

TEST(Animate, TheEffectPlanFollowsTheLightsPerFrame) {
    write_temp_file("animate_plan/scene.yaml", kAnimateScene);
    const std::string movie = write_temp_file("animate_plan/m.yaml",
        "scene: scene.yaml\nlights: [ambient]\nfps: 4\nseconds: 1\nanimate:\n"
        "  lights.spot.on: {keyframes: [{frame: 0, value: false}, {frame: 2, value: true}]}\n"
        "  lights.sun.intensity: {keyframes: [{frame: 0, value: 0.02}, {frame: 3, value: 0}]}\n"
        "  lights.sun.on: true\n");
    std::vector<std::uint64_t> shadow;
    for (int f = 0; f < 4; ++f) {
        const Job job = load_job({movie, std::nullopt, std::to_string(f)});
        shadow.push_back(PreparedScene(job.scene(), job.settings()).render(job.camera, nullptr).counts.shadow);
    }
    // Frames 0-1: the sun alone; 2: sun and spot; 3: the sun at 0 -- no rays -- and the spot.
    EXPECT_GT(shadow[0], 0u);
    EXPECT_EQ(shadow[0], shadow[1]);
    EXPECT_GT(shadow[2], shadow[1]);
    EXPECT_LT(shadow[3], shadow[2]);
    EXPECT_GT(shadow[3], 0u);
}

std::string animate_error(const std::string& name, const std::string& animate) {
    write_temp_file("animate_errors/scene.yaml", kAnimateScene);
    const std::string path = write_temp_file("animate_errors/" + name,
                                             "scene: scene.yaml\nfps: 5\nseconds: 1\nanimate:\n" + animate);
    try {
        const Job job = load_job({path});
        return "no error";
    } catch (const InputError& e) {
        return replaced(e.formatted(), path, "FILE");
    }
}

TEST(Animate, MistakesNameThePathAndTheFrame) {
    EXPECT_EQ(animate_error("radius.yaml", "  surfaces.ball.radius: {keyframes: [{frame: 0, value: 1}, {frame: 4, value: -1}]}\n"),
              "FILE:5:3: error: surfaces.ball.radius is 0 at frame 2; it must be > 0");
    EXPECT_EQ(animate_error("intensity.yaml",
                          "  lights.spot.intensity: {keyframes: [{frame: 0, value: 0}, {frame: 2, value: 0}, {frame: 4, value: 10}],"
                          " interpolation: catmull_rom}\n"),
              // The curve dips before it climbs: h11(1/2) * 2 frames * tangent 10/4 = -0.625.
              "FILE:5:3: error: lights.spot.intensity is -0.625 at frame 1; it must be >= 0");
    EXPECT_EQ(animate_error("direction.yaml", "  lights.sun.direction: {keyframes: [{frame: 0, value: [1, 0, 0]}, {frame: 2, value: [-1, 0, 0]}]}\n"),
              "FILE:5:3: error: lights.sun.direction is [0, 0, 0] at frame 1; a direction must not be zero");
    // Past what a transform may scale by, first at frame 1: 1 + (1e13 - 1) / 4 = 2.5e12.
    EXPECT_EQ(animate_error("scale.yaml", "  surfaces.tri.transform.scale: {keyframes: [{frame: 0, value: 1}, {frame: 4, value: [1, 1e13, 1]}]}\n"),
              "FILE:5:3: error: surfaces.tri.transform.scale is [1, 2.5e+12, 1] at frame 1; a scale must be 1e-12 to 1e12 in size");
    EXPECT_EQ(animate_error("unknown.yaml", "  lights.spot.radius: 2\n"),
              "FILE:5:3: error: unknown property 'radius' in 'lights.spot.radius': spot light 'spot' can animate on, "
              "intensity, color, direction, position, max_angle");
    EXPECT_EQ(animate_error("name.yaml", "  surfaces.bal.center: [0, 0, 0]\n"),
              "FILE:5:3: error: no surface named 'bal' (a surface gets one with 'name:' in the scene) (did you mean 'ball'?)");
    EXPECT_EQ(animate_error("kind.yaml", "  surface.ball.center: [0, 0, 0]\n"),
              "FILE:5:3: error: unknown property path 'surface.ball.center': a path is camera.PROPERTY, lights.NAME.PROPERTY, "
              "surfaces.NAME.PROPERTY, materials.NAME.PROPERTY or nodes.NAME.PROPERTY (did you mean 'surfaces'?)");
    EXPECT_EQ(animate_error("order.yaml", "  surfaces.ball.radius: {keyframes: [{frame: 3, value: 1}, {frame: 1, value: 2}]}\n"),
              "FILE:5:68: error: keyframes must be in increasing order: this one is at frame 1, the one before at frame 3");
    EXPECT_EQ(animate_error("flag.yaml", "  lights.sun.on: {keyframes: [{frame: 0, value: true}], interpolation: linear}\n"),
              "FILE:5:72: error: 'lights.sun.on' only steps: use interpolation: step");
    EXPECT_EQ(animate_error("twice.yaml", "  view_point: [0, 0, 1]\n  camera.view_point: [0, 0, 2]\n"),
              "FILE:6:3: error: 'camera.view_point' is animated twice");
}

TEST(Animate, AColouredMeshIsCalledAMeshInMistakes) {
    // A mesh file with vertex colours is kept as an instance of a scene
    // mesh (the world's triangles carry no colours); a mistake still calls
    // the surface what the file wrote.
    write_temp_file("animate_errors/colored.obj", "v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\nf 1 2 3\n");
    write_temp_file("animate_errors/colored.yaml",
                    replaced(kAnimateScene, "lights:\n", "  - {type: mesh, name: m, file: colored.obj, material: red}\nlights:\n"));
    const std::string path = write_temp_file("animate_errors/colored_movie.yaml",
                                             "scene: colored.yaml\nfps: 5\nseconds: 1\nanimate:\n  surfaces.m.radius: 2\n");
    try {
        load_job({path});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(replaced(e.formatted(), path, "FILE"),
                  "FILE:5:3: error: unknown property 'radius' in 'surfaces.m.radius': mesh 'm' can animate "
                  "transform.translate, transform.scale, transform.rotate.axis, transform.rotate.degrees, "
                  "transform.rotate.radians");
    }
}

TEST(Animate, TheShowcaseIsTheSameBytesForAnyShardLayout) {
    const fs::path movie = fs::path(FIRSTHIT_SOURCE_DIR) / "animations" / "showcase.yaml";
    const fs::path dir = test::temp_dir() / "showcase_shards";
    fs::remove_all(dir);
    auto frames = [&](const std::string& out, const std::string& extra) {
        const auto r = test::run_firsthit("frames " + movie.string() + " --quiet --out " + (dir / out).string() +
                                          " --range 20:44 " + extra);
        ASSERT_EQ(r.status, 0) << r.err;
    };
    frames("whole", "--threads 1");
    frames("shards", "--shard 0/3 --threads 2");
    frames("shards", "--shard 1/3 --threads 1");
    frames("shards", "--range 20:30 --shard 2/3 --threads 2");
    frames("shards", "--shard 2/3 --resume");
    for (int i = 20; i < 44; ++i) {
        const std::string name = "frame_00" + std::to_string(i) + ".png";
        EXPECT_EQ(test::slurp(dir / "whole" / name), test::slurp(dir / "shards" / name)) << name;
    }
}

}  // namespace
}  // namespace fh
