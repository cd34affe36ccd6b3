// The scene loader: the report's scene file, and bad input reported with the
// exact message, line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "text/input_error.h"
#include "yaml/scene_loader.h"
#include "yaml/scene_error.h"
#include "test_util.h"

namespace fh {
namespace {

using test::write_temp_file;

// A material and a camera, so a test can add just the part it is about.
const std::string kMaterial =
    "materials:\n"
    "  red: {color: [255, 0, 0], ambient: 0.1, diffuse: 0.5, specular: 1, phong_exponent: 10}\n";
const std::string kCamera =
    "cameras:\n"
    "  cam: {type: perspective, width: 10, height: 10, view_point: [0, 0, 5], look_at: [0, 0, -1],\n"
    "        up: [0, 1, 0], projection_distance: 1}\n";

using test::scene_error;

TEST(SceneLoader, LoadsTheReportScene) {
    const SceneFile file = load_scene(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/scene.yaml");
    const Scene& s = file.scene;
    ASSERT_EQ(s.materials.size(), 5u);
    EXPECT_EQ(s.material_names, (std::vector<std::string>{"plane", "red", "teal", "green", "metal"}));
    const Material<double>& plane = s.materials[0];
    EXPECT_EQ(plane.ambient_color, dvec3(130, 130, 130));
    EXPECT_EQ(plane.specular_color, dvec3(130, 130, 130));
    EXPECT_DOUBLE_EQ(plane.specular, 10.5);
    EXPECT_DOUBLE_EQ(plane.phong_exponent, 100);
    EXPECT_TRUE(plane.glazed);
    EXPECT_DOUBLE_EQ(plane.reflectivity, 0.05);
    EXPECT_FALSE(s.materials[1].glazed);
    EXPECT_DOUBLE_EQ(s.materials[1].reflectivity, 0);
    EXPECT_DOUBLE_EQ(s.materials[4].reflectivity, 0.6);

    ASSERT_EQ(s.spheres().size(), 3u);
    EXPECT_EQ(s.spheres()[1].center, dvec3(-3, -3, 0.5));
    EXPECT_DOUBLE_EQ(s.spheres()[1].radius, 1.5);
    EXPECT_EQ(s.spheres()[1].material, 2);
    ASSERT_EQ(s.planes.size(), 1u);
    EXPECT_EQ(s.planes[0].normal, dvec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(s.planes[0].distance, -1);
    EXPECT_EQ(s.planes[0].material, 0);
    ASSERT_EQ(s.triangles.size(), 4u);
    EXPECT_EQ(s.triangles[3].v0, dvec3(-7, 5, 0));
    EXPECT_EQ(s.triangles[3].material, 3);

    ASSERT_EQ(s.ambient_lights.size(), 1u);
    EXPECT_EQ(s.ambient_lights[0].name, "ambient");
    EXPECT_DOUBLE_EQ(s.ambient_lights[0].intensity, 0.002);
    ASSERT_EQ(s.directional_lights.size(), 1u);
    EXPECT_EQ(s.directional_lights[0].name, "directional");
    EXPECT_EQ(s.directional_lights[0].color, dvec3(255, 255, 230));
    const double k = 1 / std::sqrt(3.0);
    EXPECT_NEAR(s.directional_lights[0].direction.x, -k, 1e-15);
    EXPECT_NEAR(s.directional_lights[0].direction.y, k, 1e-15);
    EXPECT_NEAR(s.directional_lights[0].direction.z, -k, 1e-15);
    ASSERT_EQ(s.spot_lights.size(), 1u);
    EXPECT_EQ(s.spot_lights[0].name, "spot");
    EXPECT_DOUBLE_EQ(s.spot_lights[0].intensity, 2.2);
    EXPECT_EQ(s.spot_lights[0].position, dvec3(0, 0, 10));
    EXPECT_EQ(s.spot_lights[0].axis, dvec3(0, 0, -1));
    EXPECT_DOUBLE_EQ(s.spot_lights[0].max_angle, 2 * M_PI);

    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_EQ(s.cameras[0].name, "perspective");
    EXPECT_EQ(s.cameras[0].projection, Projection::perspective);
    EXPECT_DOUBLE_EQ(s.cameras[0].projection_distance, 10);
    EXPECT_EQ(s.cameras[1].name, "orthographic");
    EXPECT_EQ(s.cameras[1].projection, Projection::orthographic);
    EXPECT_EQ(s.cameras[1].width, 800);
    EXPECT_EQ(s.cameras[1].view_point, dvec3(2, -10, 10));
    EXPECT_EQ(s.cameras[1].look_at, dvec3(0, 2, -1));
    EXPECT_EQ(file.settings.samples_per_pixel, 1);
    EXPECT_EQ(file.settings.max_depth, 5);
    EXPECT_EQ(file.settings.effects.names(), "ambient diffuse specular shadows glazing");
}

TEST(SceneLoader, DefaultsAndOptionalParts) {
    const SceneFile file = load_scene(write_temp_file("minimal.yaml", kCamera));
    const Scene& s = file.scene;
    EXPECT_TRUE(s.materials.empty());
    EXPECT_TRUE(s.spheres().empty());
    EXPECT_EQ(file.settings.samples_per_pixel, 1);
    EXPECT_EQ(file.settings.max_depth, 5);
    EXPECT_EQ(file.settings.precision, Precision::float64);
    EXPECT_EQ(file.settings.effects.names(), "ambient diffuse specular shadows glazing");
}

TEST(SceneLoader, PerTermColoursRenderAndEffects) {
    const SceneFile file = load_scene(write_temp_file("terms.yaml", kCamera +
        "materials:\n"
        "  m: {ambient_color: [1, 2, 3], diffuse_color: [4, 5, 6], specular_color: [7, 8, 9],\n"
        "      ambient: 0, diffuse: 1, specular: 1, phong_exponent: 0}\n"
        "  n: {color: [10, 10, 10], specular_color: [0, 0, 0], ambient: 1, diffuse: 1, specular: 1,\n"
        "      phong_exponent: 1}\n"
        "render: {samples_per_pixel: 16, max_depth: 0, precision: float}\n"
        "effects: [diffuse, shadows]\n"));
    const Scene& s = file.scene;
    EXPECT_EQ(s.materials[0].diffuse_color, dvec3(4, 5, 6));
    EXPECT_EQ(s.materials[1].ambient_color, dvec3(10, 10, 10));
    EXPECT_EQ(s.materials[1].specular_color, dvec3(0, 0, 0));
    EXPECT_EQ(file.settings.samples_per_pixel, 16);
    EXPECT_EQ(file.settings.max_depth, 0);
    EXPECT_EQ(file.settings.precision, Precision::float32);
    EXPECT_EQ(file.settings.effects.names(), "diffuse shadows");
}

TEST(SceneLoader, PlaneNormalIsNormalizedKeepingThePlane) {
    const Scene s = load_scene(write_temp_file("plane.yaml", kMaterial + kCamera +
        "surfaces:\n"
        "  - {type: plane, normal: [0, 0, 4], distance: -8, material: red}\n")).scene;
    EXPECT_EQ(s.planes[0].normal, dvec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(s.planes[0].distance, -2);
}

TEST(SceneLoader, DegenerateTriangleIsAccepted) {
    const Scene s = load_scene(write_temp_file("flat.yaml", kMaterial + kCamera +
        "surfaces:\n"
        "  - {type: triangle, vertices: [[0, 0, 0], [1, 1, 1], [2, 2, 2]], material: red}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.triangles[0].normal, dvec3(0));
}

TEST(SceneLoader, MissingFile) {
    const std::string path = test::temp_dir().string() + "/no_such.yaml";
    try {
        load_scene(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), path + ": error: cannot read file: no such file");
    }
}

TEST(SceneLoader, YamlSyntaxError) {
    EXPECT_EQ(scene_error(kCamera + "surfaces: [{type: sphere\n"),
              "FILE:5:1: error: invalid yaml: end of map flow not found (the '{' at line 4, column 12 is never closed)");
}

TEST(SceneLoader, EmptyFile) {
    EXPECT_EQ(scene_error(""), "FILE: error: empty scene file");
    EXPECT_EQ(scene_error("# nothing but a comment\n"), "FILE: error: empty scene file");
}

TEST(SceneLoader, TopLevelNotAMap) {
    EXPECT_EQ(scene_error("- 1\n- 2\n"), "FILE:1:1: error: expected a map at the top level, got a list");
}

TEST(SceneLoader, UnknownTopLevelKey) {
    EXPECT_EQ(scene_error(kCamera + "surface: []\n"),
              "FILE:4:1: error: unknown key 'surface' in scene (did you mean 'surfaces'?)");
}

TEST(SceneLoader, UnknownKeyWithSuggestion) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radus: 1, material: red}\n"),
              "FILE:7:39: error: unknown key 'radus' in sphere (did you mean 'radius'?)");
}

TEST(SceneLoader, UnknownKeyWithoutSuggestion) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 1, material: red, shiny: 1}\n"),
              "FILE:7:65: error: unknown key 'shiny' in sphere");
}

TEST(SceneLoader, MissingKey) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], material: red}\n"),
              "FILE:7:5: error: missing key 'radius' in sphere");
}

TEST(SceneLoader, DuplicateKey) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 1, radius: 2, material: red}\n"),
              "FILE:7:50: error: duplicate key 'radius' in surface");
}

TEST(SceneLoader, WrongType) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: big, material: red}\n"),
              "FILE:7:47: error: expected a number for 'radius', got 'big'");
    // A quoted number is text, not a number.
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: \"1\", material: red}\n"),
              "FILE:7:47: error: expected a number for 'radius', got '1'");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0], radius: 1, material: red}\n"),
              "FILE:7:28: error: expected a list of 3 numbers for 'center'");
}

TEST(SceneLoader, UnknownSurfaceType) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: spher, center: [0, 0, 0], radius: 1, material: red}\n"),
              "FILE:7:12: error: unknown surface type 'spher' (did you mean 'sphere'?)");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: cube, material: red}\n"),
              "FILE:7:12: error: unknown surface type 'cube' (expected sphere, plane, triangle, mesh, instance, instances, group, disk or gltf)");
}

TEST(SceneLoader, UndefinedMaterial) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 1, material: reed}\n"),
              "FILE:7:60: error: undefined material 'reed' (did you mean 'red'?)");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 1, material: gold}\n"),
              "FILE:7:60: error: undefined material 'gold'");
}

TEST(SceneLoader, RadiusMustBePositive) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: -1, material: red}\n"),
              "FILE:7:47: error: 'radius' must be > 0, got -1");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 0, material: red}\n"),
              "FILE:7:47: error: 'radius' must be > 0, got 0");
}

TEST(SceneLoader, ZeroLengthNormal) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: plane, normal: [0, 0, 0], distance: 1, material: red}\n"),
              "FILE:7:27: error: 'normal' must not be zero-length");
}

TEST(SceneLoader, ZeroLightDirection) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  sun: {type: directional, color: [255, 255, 255], intensity: 1,\n"
                          "        direction: [0, 0, 0]}\n"),
              "FILE:6:20: error: 'direction' must not be zero-length");
}

TEST(SceneLoader, ZeroLookAt) {
    EXPECT_EQ(scene_error("cameras:\n"
                          "  cam:\n"
                          "    type: orthographic\n"
                          "    width: 10\n"
                          "    height: 10\n"
                          "    view_point: [0, 0, 0]\n"
                          "    look_at: [0, 0, 0]\n"
                          "    up: [0, 0, 1]\n"),
              "FILE:7:14: error: 'look_at' must not be zero-length");
}

TEST(SceneLoader, NotANumberAndInfinity) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  amb: {type: ambient, color: [255, 255, 255], intensity: .nan}\n"),
              "FILE:5:59: error: 'intensity' must be finite");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, -.inf, 0], radius: 1, material: red}\n"),
              "FILE:7:32: error: 'center' must be finite");
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: sphere, center: [0, 0, 0], radius: 1e999, material: red}\n"),
              "FILE:7:47: error: 'radius' must be finite");
}

TEST(SceneLoader, ColourOutOfRange) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  amb: {type: ambient, color: [255, 256, 255], intensity: 1}\n"),
              "FILE:5:37: error: 'color' components must be in 0..255, got 256");
}

TEST(SceneLoader, NegativeStrength) {
    EXPECT_EQ(scene_error(kCamera +
                          "materials:\n"
                          "  m: {color: [1, 1, 1], ambient: 0.1, diffuse: -0.5, specular: 1, phong_exponent: 1}\n"),
              "FILE:5:48: error: 'diffuse' must be >= 0, got -0.5");
}

TEST(SceneLoader, ImageSize) {
    const std::string head = "cameras:\n  cam: {type: orthographic, view_point: [0, 0, 0], look_at: [0, 0, -1],\n";
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 0, height: 10}\n"),
              "FILE:3:31: error: 'width' must be between 1 and 16384, got 0");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 100000, height: 10}\n"),
              "FILE:3:31: error: 'width' must be between 1 and 16384, got 100000");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 99999999999999999999, height: 10}\n"),
              "FILE:3:31: error: 'width' must be between 1 and 16384, got 99999999999999999999");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 10.5, height: 10}\n"),
              "FILE:3:31: error: expected an integer for 'width', got '10.5'");
}

TEST(SceneLoader, ImageSizeNegativeAndHeight) {
    const std::string head = "cameras:\n  cam: {type: orthographic, view_point: [0, 0, 0], look_at: [0, 0, -1],\n";
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: -5, height: 10}\n"),
              "FILE:3:31: error: 'width' must be between 1 and 16384, got -5");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 10, height: 0}\n"),
              "FILE:3:43: error: 'height' must be between 1 and 16384, got 0");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 100000, height: 100000}\n"),
              "FILE:3:31: error: 'width' must be between 1 and 16384, got 100000");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: 16384, height: 16385}\n"),
              "FILE:3:46: error: 'height' must be between 1 and 16384, got 16385");
    EXPECT_EQ(scene_error(head + "        up: [0, 1, 0], width: .nan, height: 1}\n"),
              "FILE:3:31: error: expected an integer for 'width', got '.nan'");
}

TEST(SceneLoader, ZeroLengthUp) {
    EXPECT_EQ(scene_error("cameras:\n"
                          "  cam: {type: orthographic, width: 1, height: 1, view_point: [0, 0, 0],\n"
                          "        look_at: [0, 0, -1], up: [0, 0, 0]}\n"),
              "FILE:3:34: error: 'up' must not be zero-length");
}

TEST(SceneLoader, ZeroLengthSpotDirection) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  s: {type: spot, color: [255, 255, 255], intensity: 1, position: [0, 0, 1],\n"
                          "      direction: [0, -0.0, 0]}\n"),
              "FILE:6:18: error: 'direction' must not be zero-length");
}

TEST(SceneLoader, InfinityAndNotANumberEverywhere) {
    // Every kind of number refuses .inf and .nan in all their spellings.
    EXPECT_EQ(scene_error(kCamera + "lights:\n  s: {type: spot, color: [255, 255, 255], intensity: 1,"
                                    " position: [0, 0, .Inf], direction: [0, 0, -1]}\n"),
              "FILE:5:74: error: 'position' must be finite");
    EXPECT_EQ(scene_error(kCamera + "lights:\n  s: {type: spot, color: [255, 255, 255], intensity: 1,"
                                    " position: [0, 0, 1], direction: [0, 0, -1], max_angle: .NaN}\n"),
              "FILE:5:112: error: 'max_angle' must be finite");
    EXPECT_EQ(scene_error(kCamera + "materials:\n  m: {color: [1, 1, .nan], ambient: 0, diffuse: 0,"
                                    " specular: 0, phong_exponent: 1}\n"),
              "FILE:5:21: error: 'color' must be finite");
    EXPECT_EQ(scene_error(kCamera + "materials:\n  m: {color: [1, 1, 1], ambient: 0, diffuse: 0,"
                                    " specular: 0, phong_exponent: +.inf}\n"),
              "FILE:5:78: error: 'phong_exponent' must be finite");
    EXPECT_EQ(scene_error("cameras:\n  c: {type: perspective, width: 1, height: 1, view_point: [0, 0, 0],"
                          " look_at: [0, 0, -1], up: [0, 1, 0], projection_distance: -.inf}\n"),
              "FILE:2:127: error: 'projection_distance' must be finite");
}

TEST(SceneLoader, ProjectionDistanceOnlyForPerspective) {
    EXPECT_EQ(scene_error("cameras:\n"
                          "  o: {type: orthographic, width: 1, height: 1, view_point: [0, 0, 0],\n"
                          "      look_at: [0, 0, -1], up: [0, 1, 0], projection_distance: 1}\n"),
              "FILE:3:43: error: unknown key 'projection_distance' in orthographic camera 'o'");
}

TEST(SceneLoader, NoCamera) {
    EXPECT_EQ(scene_error(kMaterial), "FILE:1:1: error: missing key 'cameras' in scene");
    EXPECT_EQ(scene_error("cameras: {}\n"), "FILE:1:10: error: 'cameras' must name at least one camera");
}

TEST(SceneLoader, RenderLimits) {
    EXPECT_EQ(scene_error(kCamera + "render: {samples_per_pixel: 5000}\n"),
              "FILE:4:29: error: 'samples_per_pixel' must be between 1 and 4096, got 5000");
    EXPECT_EQ(scene_error(kCamera + "render: {max_depth: -1}\n"),
              "FILE:4:21: error: 'max_depth' must be between 0 and 64, got -1");
    EXPECT_EQ(scene_error(kCamera + "render: {precision: half}\n"),
              "FILE:4:21: error: unknown precision 'half' (expected float or double)");
}

TEST(SceneLoader, RenderLimitsAtAndPastTheEdges) {
    EXPECT_EQ(scene_error(kCamera + "render: {samples_per_pixel: 0}\n"),
              "FILE:4:29: error: 'samples_per_pixel' must be between 1 and 4096, got 0");
    EXPECT_EQ(scene_error(kCamera + "render: {max_depth: 65}\n"),
              "FILE:4:21: error: 'max_depth' must be between 0 and 64, got 65");
    EXPECT_EQ(scene_error(kCamera + "render: {max_depth: 1000000000000}\n"),
              "FILE:4:21: error: 'max_depth' must be between 0 and 64, got 1000000000000");
    const std::string path = test::write_temp_file("edges.yaml", kCamera + "render: {samples_per_pixel: 4096, max_depth: 64}\n");
    const SceneFile file = load_scene(path);
    const Scene& s = file.scene;
    EXPECT_EQ(file.settings.samples_per_pixel, 4096);
    EXPECT_EQ(file.settings.max_depth, 64);
}

TEST(SceneLoader, UnknownEffect) {
    EXPECT_EQ(scene_error(kCamera + "effects: [ambient, shadow]\n"),
              "FILE:4:20: error: unknown effect 'shadow' (did you mean 'shadows'?)");
}

TEST(SceneLoader, SecondAmbientLight) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  a1: {type: ambient, color: [255, 255, 255], intensity: 1}\n"
                          "  a2: {type: ambient, color: [255, 255, 255], intensity: 1}\n"),
              "FILE:6:3: error: second ambient light 'a2' (at most one is allowed)");
}

TEST(SceneLoader, MissingValue) {
    EXPECT_EQ(scene_error(kCamera +
                          "lights:\n"
                          "  a:\n"
                          "    type: ambient\n"
                          "    color:\n"
                          "    intensity: 1\n"),
              "FILE:7:5: error: missing value for 'color'");
}

TEST(SceneLoader, BadBoolean) {
    EXPECT_EQ(scene_error(kCamera +
                          "materials:\n"
                          "  m: {color: [1, 1, 1], ambient: 0, diffuse: 0, specular: 0, phong_exponent: 1,\n"
                          "      glazed: maybe}\n"),
              "FILE:6:15: error: expected true or false for 'glazed', got 'maybe'");
}

TEST(SceneLoader, TriangleNeedsThreeVertices) {
    EXPECT_EQ(scene_error(kMaterial + kCamera +
                          "surfaces:\n"
                          "  - {type: triangle, vertices: [[0, 0, 0], [1, 0, 0]], material: red}\n"),
              "FILE:7:32: error: expected a list of 3 points for 'vertices'");
}

}  // namespace
}  // namespace fh

namespace fh {
namespace {

TEST(SceneLoaderWarnings, LikelyUnitMistakesWarnAndTheReportSceneDoesNot) {
    const std::string text =
        "materials:\n  m: {color: [1, 0.5, 0.5], ambient: 0.1, diffuse: 0.5, specular: 0, phong_exponent: 1}\n"
        "lights:\n  s: {type: spot, color: [1, 1, 1], intensity: 1, position: [0, 0, 5], direction: [0, 0, -1],"
        " max_angle: 45}\n"
        "cameras:\n  c: {type: perspective, width: 8, height: 8, view_point: [0, -5, 0], look_at: [0, 1, 0],"
        " up: [0, 0, 1], projection_distance: 2000}\n"
        "  w: {type: perspective, width: 8, height: 8, view_point: [0, -5, 0], look_at: [0, 1, 0],"
        " up: [0, 0, 1], projection_distance: 0.5}\n";
    const SceneFile f = load_scene_from_string(text, "s.yaml");
    ASSERT_EQ(f.warnings.size(), 4u);
    EXPECT_EQ(f.warnings[0], "s.yaml: warning: every colour is at most 1: 0-1 colours? firsthit's colours are 0-255, "
                             "so the image comes out nearly black");
    EXPECT_EQ(f.warnings[1], "s.yaml: warning: spot light 's': max_angle 45 is over 2 pi: degrees? max_angle is in radians");
    // 2 atan(10 / 2000) = 0.573 degrees; 2 atan(10 / 0.5) = 2 atan(20) = 174.3 degrees.
    EXPECT_EQ(f.warnings[2], "s.yaml: warning: camera 'c': projection_distance 2000 gives a field of view of 0.573 "
                             "degrees (10 gives 90)");
    EXPECT_EQ(f.warnings[3], "s.yaml: warning: camera 'w': projection_distance 0.5 gives a field of view of 174.3 "
                             "degrees (10 gives 90)");
    EXPECT_TRUE(load_scene(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/scene.yaml").warnings.empty());
}

}  // namespace
}  // namespace fh
