// The movie loader: the report's two movies, paths, overrides, and bad input
// reported with the exact message, line and column.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "test_util.h"

namespace fh {
namespace {

using test::write_temp_file;

// The scene the test movies name, in the folder movies/.
const std::string kMovieScene =
    "cameras:\n"
    "  persp: {type: perspective, width: 10, height: 10, view_point: [0, 0, 5], look_at: [0, 0, -1],\n"
    "          up: [0, 1, 0], projection_distance: 1}\n"
    "  ortho: {type: orthographic, width: 20, height: 10, view_point: [0, 0, 5], look_at: [0, 0, -1],\n"
    "          up: [0, 1, 0]}\n"
    "lights:\n"
    "  amb: {type: ambient, color: [255, 255, 255], intensity: 0.1}\n"
    "  sun: {type: directional, color: [255, 255, 255], intensity: 1, direction: [0, 0, -1]}\n"
    "  spot: {type: spot, color: [255, 255, 255], intensity: 1, position: [0, 0, 9], direction: [0, 0, -1]}\n"
    "render: {samples_per_pixel: 2, max_depth: 3}\n";

std::string movie_path(const std::string& yaml) {
    write_temp_file("movies/scene.yaml", kMovieScene);
    return write_temp_file("movies/movie.yaml", yaml);
}

// The formatted error of loading `yaml` as a movie, its path shown as FILE
// and the movies folder as DIR.
std::string movie_error(const std::string& yaml) {
    std::string s = test::check_error(movie_path(yaml), [](const std::string& p) { load_movie(p); });
    const std::string dir = (test::temp_dir() / "movies").string();
    if (const auto at = s.find(dir); at != std::string::npos) s.replace(at, dir.size(), "DIR");
    return s;
}

// The path animating `property` ("camera.view_point"), or nullptr.
const Path* path_of(const Movie& m, const std::string& property) {
    for (const Animation& a : m.animations)
        if (a.target.path == property) return &a.path;
    return nullptr;
}

TEST(MovieLoader, LoadsTheReportMovies) {
    const std::string dir = std::string(FIRSTHIT_SOURCE_DIR) + "/animations/";
    const Movie m1 = load_movie(dir + "movie1.yaml");
    EXPECT_EQ(m1.camera.name, "perspective");
    EXPECT_DOUBLE_EQ(m1.fps, 30);
    EXPECT_DOUBLE_EQ(m1.seconds, 10);
    // Lights that are not listed stay in the scene, switched off.
    ASSERT_EQ(m1.scene.ambient_lights.size(), 1u);
    ASSERT_EQ(m1.scene.directional_lights.size(), 1u);
    ASSERT_EQ(m1.scene.spot_lights.size(), 1u);
    EXPECT_TRUE(m1.scene.ambient_lights[0].on);
    EXPECT_FALSE(m1.scene.directional_lights[0].on);
    EXPECT_TRUE(m1.scene.spot_lights[0].on);
    ASSERT_TRUE(path_of(m1, "camera.view_point") && std::holds_alternative<Orbit>(*path_of(m1, "camera.view_point")));
    const Orbit& orbit = std::get<Orbit>(*path_of(m1, "camera.view_point"));
    EXPECT_EQ(orbit.center, dvec3(-10, -10, 16));
    EXPECT_EQ(orbit.sin, dvec3(20, 0, 0));
    EXPECT_EQ(orbit.cos, dvec3(0, 0, 15));
    EXPECT_DOUBLE_EQ(orbit.turns, 1);
    ASSERT_TRUE(path_of(m1, "camera.look_at") && std::holds_alternative<Toward>(*path_of(m1, "camera.look_at")));
    EXPECT_EQ(std::get<dvec3>(std::get<Toward>(*path_of(m1, "camera.look_at")).point), dvec3(0));
    EXPECT_FALSE(path_of(m1, "camera.up"));

    const Movie m2 = load_movie(dir + "movie2.yaml");
    EXPECT_EQ(m2.camera.name, "orthographic");
    EXPECT_TRUE(m2.scene.directional_lights[0].on);
    EXPECT_FALSE(m2.scene.spot_lights[0].on);
    EXPECT_EQ(std::get<Orbit>(*path_of(m2, "camera.view_point")).center, dvec3(-10, -40, 26));
}

TEST(MovieLoader, IsMovieFile) {
    EXPECT_TRUE(is_movie_file(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/movie1.yaml"));
    EXPECT_FALSE(is_movie_file(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/scene.yaml"));
    EXPECT_FALSE(is_movie_file(test::temp_dir().string() + "/no_such.yaml"));
    EXPECT_FALSE(is_movie_file(write_temp_file("broken.yaml", "a: [1\n")));
}

TEST(MovieLoader, DefaultsOverridesAndFixedValues) {
    const Movie m = load_movie(movie_path(
        "scene: scene.yaml\n"
        "camera: ortho\n"
        "render: {samples_per_pixel: 8}\n"
        "effects: [ambient]\n"
        "animate:\n"
        "  view_point: [1, 2, 3]\n"
        "  up: {value: [0, 0, 1]}\n"));
    EXPECT_EQ(m.camera.name, "ortho");
    EXPECT_EQ(m.camera.width, 20);
    EXPECT_DOUBLE_EQ(m.fps, 30);
    EXPECT_DOUBLE_EQ(m.seconds, 10);
    EXPECT_EQ(m.scene.ambient_lights.size() + m.scene.directional_lights.size() + m.scene.spot_lights.size(), 3u);
    EXPECT_EQ(m.settings.samples_per_pixel, 8);
    EXPECT_EQ(m.settings.max_depth, 3);  // the scene's, not overridden
    EXPECT_EQ(m.settings.effects.names(), "ambient");
    EXPECT_EQ(std::get<dvec3>(*path_of(m, "camera.view_point")), dvec3(1, 2, 3));
    EXPECT_EQ(std::get<dvec3>(*path_of(m, "camera.up")), dvec3(0, 0, 1));
    EXPECT_FALSE(path_of(m, "camera.look_at"));
}

TEST(MovieLoader, CameraDefaultsToTheFirst) {
    const Movie m = load_movie(movie_path("scene: scene.yaml\nlights: []\nfps: 24\nseconds: 0.5\n"));
    EXPECT_EQ(m.camera.name, "persp");
    EXPECT_DOUBLE_EQ(m.fps, 24);
    EXPECT_DOUBLE_EQ(m.seconds, 0.5);
    for (const auto& l : m.scene.ambient_lights) EXPECT_FALSE(l.on);
    for (const auto& l : m.scene.spot_lights) EXPECT_FALSE(l.on);
}

TEST(MovieLoader, KeyframesInOrderWithInterpolation) {
    const Movie m = load_movie(movie_path(
        "scene: scene.yaml\n"
        "animate:\n"
        "  look_at:\n"
        "    keyframes: [{frame: 0, value: [0, 1, 0]}, {time: 1, value: [1, 0, 0]}]\n"
        "    interpolation: catmull_rom\n"));
    ASSERT_TRUE(path_of(m, "camera.look_at") && std::holds_alternative<Keyframes>(*path_of(m, "camera.look_at")));
    const Keyframes& k = std::get<Keyframes>(*path_of(m, "camera.look_at"));
    ASSERT_EQ(k.keys.size(), 2u);
    EXPECT_EQ(k.keys[0].frame, 0);
    EXPECT_EQ(k.keys[0].value, dvec3(0, 1, 0));
    EXPECT_EQ(k.keys[1].frame, 30);  // 1 s at the default 30 fps
    EXPECT_EQ(k.interpolation, Interpolation::catmull_rom);
}

TEST(MovieLoader, MissingSceneFile) {
    EXPECT_EQ(movie_error("camera: persp\nscene: nothing.yaml\n"),
              "FILE:2:8: error: scene file 'DIR/nothing.yaml': no such file");
}

TEST(MovieLoader, SceneIsADirectory) {
    EXPECT_EQ(movie_error("scene: .\n"), "FILE:1:8: error: scene file 'DIR/.': is a folder");
}

TEST(MovieLoader, SceneIsTheMovieItself) {
    EXPECT_EQ(movie_error("scene: movie.yaml\n"), "FILE:1:8: error: a movie cannot be its own scene");
}

TEST(MovieLoader, SceneIsNotARegularFile) {
    EXPECT_EQ(movie_error("scene: /dev/zero\n"), "FILE:1:8: error: scene file '/dev/zero': not a regular file");
}

TEST(MovieLoader, SceneIsAnotherMovie) {
    write_temp_file("movies/other_movie.yaml", "scene: scene.yaml\n");
    EXPECT_EQ(movie_error("scene: other_movie.yaml\n"),
              "FILE:1:8: error: scene file 'DIR/other_movie.yaml' is a movie, not a scene");
}

TEST(MovieLoader, SceneNameIsEmptyOrNotAName) {
    EXPECT_EQ(movie_error("scene:\n"), "FILE:1:1: error: missing value for 'scene'");
    EXPECT_EQ(movie_error("scene: [a.yaml]\n"), "FILE:1:8: error: expected a name for 'scene', got a list");
    EXPECT_EQ(movie_error("scene: \"\"\n"), "FILE:1:8: error: 'scene' names no file (it is empty)");
}

TEST(MovieLoader, EmptyAndBinaryMovieFiles) {
    EXPECT_EQ(movie_error(""), "FILE: error: empty movie file");
    EXPECT_EQ(movie_error(std::string("scene: scene.yaml\n\0\0", 20)),
              "FILE:2:1: error: binary data, not text: control byte 0x00 (scene and movie files are UTF-8 text)");
}

TEST(MovieLoader, FromStringResolvesTheSceneNextToThePath) {
    movie_path("scene: scene.yaml\n");  // writes the scene
    const std::string path = (test::temp_dir() / "movies" / "in_memory.yaml").string();
    const Movie m = load_movie_from_string("scene: scene.yaml\ncamera: ortho\nfps: 2\nseconds: 3\n", path);
    EXPECT_EQ(m.camera.name, "ortho");
    EXPECT_EQ(m.frame_count(), 6);
    try {
        load_movie_from_string("scene: scene.yaml\nfps: 0\n", path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), path + ":2:6: error: 'fps' must be > 0, got 0");
    }
}

TEST(MovieLoader, ManyKeyframesAreCheckedInLinearTime) {
    std::string yaml = "scene: scene.yaml\nseconds: 1000\nanimate:\n  view_point:\n    keyframes:\n";
    for (int i = 0; i < 20000; ++i) yaml += "      - {frame: " + std::to_string(i) + ", value: [0, 0, 1]}\n";
    yaml += "      - {frame: 19999, value: [0, 0, 1]}\n";
    EXPECT_EQ(movie_error(yaml), "FILE:20006:17: error: two keyframes at frame 19999");
}

TEST(MovieLoader, ErrorInTheSceneIsReportedAgainstTheScene) {
    write_temp_file("movies/bad_scene.yaml", "cameras: {}\n");
    EXPECT_EQ(movie_error("scene: bad_scene.yaml\n"),
              "DIR/bad_scene.yaml:1:10: error: 'cameras' must name at least one camera");
}

TEST(MovieLoader, UndefinedCamera) {
    EXPECT_EQ(movie_error("scene: scene.yaml\ncamera: perp\n"),
              "FILE:2:9: error: undefined camera 'perp' (did you mean 'persp'?)");
    // Nothing close: the scene's cameras are listed, as --camera lists them.
    const std::string listed = movie_error("scene: scene.yaml\ncamera: zzz\n");
    EXPECT_EQ(listed.rfind("FILE:2:9: error: undefined camera 'zzz' (the scene's cameras: 'persp'", 0), 0u) << listed;
}

TEST(MovieLoader, UndefinedLight) {
    EXPECT_EQ(movie_error("scene: scene.yaml\nlights: [amb, moon]\n"), "FILE:2:15: error: undefined light 'moon'");
}

TEST(MovieLoader, FpsAndSecondsMustBePositive) {
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: 0\n"), "FILE:2:6: error: 'fps' must be > 0, got 0");
    EXPECT_EQ(movie_error("scene: scene.yaml\nseconds: -1\n"), "FILE:2:10: error: 'seconds' must be > 0, got -1");
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: .inf\n"), "FILE:2:6: error: 'fps' must be finite");
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: -30\n"), "FILE:2:6: error: 'fps' must be > 0, got -30");
    EXPECT_EQ(movie_error("scene: scene.yaml\nseconds: 0\n"), "FILE:2:10: error: 'seconds' must be > 0, got 0");
    EXPECT_EQ(movie_error("scene: scene.yaml\nseconds: -0.0\n"), "FILE:2:10: error: 'seconds' must be > 0, got -0.0");
    EXPECT_EQ(movie_error("scene: scene.yaml\nseconds: .nan\n"), "FILE:2:10: error: 'seconds' must be finite");
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: thirty\n"), "FILE:2:6: error: expected a number for 'fps', got 'thirty'");
}

TEST(MovieLoader, FrameCountLimits) {
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: 1\nseconds: 0.2\n"),
              "FILE:3:10: error: fps * seconds gives no frames");
    EXPECT_EQ(movie_error("scene: scene.yaml\nfps: 1000\nseconds: 1e6\n"),
              "FILE:3:10: error: fps * seconds gives more than 1000000 frames");
}

TEST(MovieLoader, TowardOnlyForLookAt) {
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  view_point: {toward: [0, 0, 0]}\n"),
              "FILE:3:16: error: 'toward' is only allowed for 'camera.look_at' and a spot light's 'direction'");
}

// 'toward' a light that has no position says so (it said "no such thing").
TEST(MovieLoader, TowardALightWithoutAPosition) {
    EXPECT_EQ(movie_error("scene: scene.yaml\nanimate:\n  look_at: {toward: lights.sun}\n"),
              "FILE:3:21: error: 'toward' cannot follow a directional light: it has no position");
    EXPECT_EQ(movie_error("scene: scene.yaml\nanimate:\n  look_at: {toward: lights.amb}\n"),
              "FILE:3:21: error: 'toward' cannot follow an ambient light: it has no position");
}

TEST(MovieLoader, OnePathKindPerProperty) {
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  look_at: {value: [0, 0, -1], toward: [0, 0, 0]}\n"),
              "FILE:3:32: error: 'look_at' takes only one of 'value', 'orbit', 'toward' or 'keyframes'");
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  look_at: {value: [0, 0, -1], interpolation: linear}\n"),
              "FILE:3:32: error: 'interpolation' only applies to 'keyframes'");
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  up: {orbt: {}}\n"),
              "FILE:3:8: error: unknown key 'orbt' in 'up' (did you mean 'orbit'?)");
}

TEST(MovieLoader, DuplicateKeyframes) {
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  view_point:\n"
                          "    keyframes:\n"
                          "      - {frame: 10, value: [0, 0, 0]}\n"
                          "      - {frame: 10, value: [1, 0, 0]}\n"),
              "FILE:6:17: error: two keyframes at frame 10");
}

TEST(MovieLoader, ZeroLookAtValue) {
    EXPECT_EQ(movie_error("scene: scene.yaml\n"
                          "animate:\n"
                          "  look_at: [0, 0, 0]\n"),
              "FILE:3:12: error: 'camera.look_at' must not be zero-length");
}

TEST(MovieLoader, UnknownMovieKey) {
    EXPECT_EQ(movie_error("scene: scene.yaml\nframes_per_second: 30\n"),
              "FILE:2:1: error: unknown key 'frames_per_second' in movie");
}

}  // namespace
}  // namespace fh
