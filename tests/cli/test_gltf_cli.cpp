// glTF files from the command line: `export` writes the world positions
// worked out by hand (hierarchy, the file's animation, y-up turned z-up, a
// YAML scene's placement, a movie's `nodes.NAME.*` paths), `frames` renders
// as many frames as the animation lasts, `--camera` picks the file's
// cameras by name or index, and each mistake is one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli/run_command.h"
#include "core/vec.h"
#include "gltf/gltf_builder.h"
#include "meshes/mesh_loader.h"
#include "support/png_read.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;
using namespace fh::gltf_test;

// Node "base" (scale 2, its translation animated LINEAR from (0,0,0) at 0 s
// to (0,3,0) at 1 s) holds node "arm" (translation (1,2,3)) holding the
// triangle (0,0,0) (1,0,0) (0,1,0); cameras "near" and "far" on nodes at
// z = 10 and z = 20 looking down -z at it.
std::string model() {
    Bin bin;
    const int positions = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int times = bin.f32({0, 1});
    const int moves = bin.f32({0, 0, 0, 0, 3, 0});
    const std::string v = std::to_string(positions), t = std::to_string(times), m = std::to_string(moves);
    return gltf_json(R"("scenes": [{"nodes": [0, 2, 3]}],
"nodes": [{"name": "base", "scale": [2, 2, 2], "children": [1]}, {"name": "arm", "translation": [1, 2, 3], "mesh": 0},
          {"name": "near node", "camera": 0, "translation": [0.5, 0.5, 10]},
          {"name": "far node", "camera": 1, "translation": [0.5, 0.5, 20]}],
"cameras": [{"name": "near", "type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1, "znear": 0.1}},
            {"name": "far", "type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1, "znear": 0.1}}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"accessors": [{"bufferView": )" + v + R"(, "componentType": 5126, "count": 3, "type": "VEC3"},
              {"bufferView": )" + t + R"(, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
              {"bufferView": )" + m + R"(, "componentType": 5126, "count": 2, "type": "VEC3"}],
"animations": [{"name": "slide", "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
                "samplers": [{"input": 1, "output": 2, "interpolation": "LINEAR"}]}])",
                     bin);
}

fs::path model_dir(const std::string& name) {
    const fs::path dir = fresh_dir(name);
    std::ofstream(dir / "model.gltf") << model();
    return dir;
}

// DIR/scene.yaml: a grey material, an ambient light, a 32 x 32 camera
// (`view`: its view_point and look_at) and the one surface `surface`.
void write_yaml_scene(const fs::path& dir, const std::string& view, const std::string& surface) {
    std::ofstream(dir / "scene.yaml")
        << "materials:\n  grey: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
           "lights:\n  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.2}\n"
           "cameras:\n  front: {type: perspective, width: 32, height: 32, "
        << view << ", up: [0, 0, 1], projection_distance: 10}\nsurfaces:\n  - " << surface << "\n";
}

// The vertices `firsthit export ARGS -o OUT.obj` writes.
std::vector<dvec3> exported(const std::string& args, const fs::path& dir) {
    const fs::path out = dir / "out.obj";
    const auto r = run_firsthit("export " + args + " --quiet -o " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    std::vector<dvec3> v;
    std::ifstream in(out);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag;
        dvec3 p;
        if (words >> tag >> p.x >> p.y >> p.z && tag == "v") v.push_back(p);
    }
    return v;
}

void expect_points_near(const std::vector<dvec3>& got, const std::vector<dvec3>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[i][k], want[i][k], 1e-9) << "vertex " << i << " axis " << k;
}

// A file point p lands at base(t) + 2 (arm + p), then y-up turns z-up:
// (x, y, z) -> (x, -z, y). At frame 15 of 30 fps (0.5 s) base is (0,1.5,0):
//   (0,0,0) -> (2,4,6)+(0,1.5,0) = (2,5.5,6) -> (2,-6,5.5)
//   (1,0,0) -> (4,4,6)+(0,1.5,0) = (4,5.5,6) -> (4,-6,5.5)
//   (0,1,0) -> (2,6,6)+(0,1.5,0) = (2,7.5,6) -> (2,-6,7.5)
TEST(GltfCli, ExportIsTheWorldAfterHierarchyAndAnimation) {
    const fs::path dir = model_dir("gltf_export");
    const std::string file = (dir / "model.gltf").string();
    expect_points_near(exported(file + " --frame 15", dir), {{2, -6, 5.5}, {4, -6, 5.5}, {2, -6, 7.5}});
    // At 10 fps frame 5 is the same 0.5 s; frame 0 has base at the origin.
    expect_points_near(exported(file + " --frame 5 --fps 10", dir), {{2, -6, 5.5}, {4, -6, 5.5}, {2, -6, 7.5}});
    expect_points_near(exported(file + " --frame 0", dir), {{2, -6, 4}, {4, -6, 4}, {2, -6, 6}});
}

// Placed in a YAML scene, translated by (10, 0, 0) after the z-up turn.
TEST(GltfCli, ExportOfAYamlSceneHoldingTheFile) {
    const fs::path dir = model_dir("gltf_export_yaml");
    write_yaml_scene(dir, "view_point: [0, -20, 5], look_at: [0, 1, 0]",
                     "{type: gltf, name: model, file: model.gltf, transform: {translate: [10, 0, 0]}}");
    expect_points_near(exported((dir / "scene.yaml").string(), dir), {{12, -6, 4}, {14, -6, 4}, {12, -6, 6}});
}

// Vertex colours are written where a mesh has them: a coloured OBJ placed
// at x + 10 (a `type: mesh` with colours is an instance) beside an
// uncoloured one (the world's own triangles, white). OBJ keeps the values;
// PLY writes bytes, round(255 c): 0.5 -> 128, 0.25 -> 64. A scene without
// colours writes plain vertices.
TEST(GltfCli, ExportWritesVertexColoursWhereAMeshHasThem) {
    const fs::path dir = fresh_dir("export_colours");
    std::ofstream(dir / "colored.obj") << "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 0.25\nf 1 2 3\n";
    std::ofstream(dir / "plain.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    write_yaml_scene(dir, "view_point: [0, -20, 5], look_at: [0, 1, 0]",
                     "{type: mesh, file: plain.obj, material: grey}\n"
                     "  - {type: mesh, file: colored.obj, material: grey, transform: {translate: [10, 0, 0]}}");
    const std::vector<std::pair<dvec3, dvec3>> want = {
        {{0, 0, 0}, {1, 1, 1}},  {{1, 0, 0}, {1, 1, 1}},    {{0, 1, 0}, {1, 1, 1}},
        {{10, 0, 0}, {1, 0, 0}}, {{11, 0, 0}, {0, 0.5, 0}}, {{10, 1, 0}, {0, 0, 0.25}}};

    const auto obj = run_firsthit("export " + (dir / "scene.yaml").string() + " --quiet -o " + (dir / "out.obj").string());
    ASSERT_EQ(obj.status, 0) << obj.err;
    std::vector<std::pair<dvec3, dvec3>> got;
    std::ifstream in(dir / "out.obj");
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag;
        dvec3 p, c;
        if (words >> tag >> p.x >> p.y >> p.z >> c.x >> c.y >> c.z && tag == "v") got.push_back({p, c});
    }
    EXPECT_EQ(got, want);

    const auto ply = run_firsthit("export " + (dir / "scene.yaml").string() + " --quiet -o " + (dir / "out.ply").string());
    ASSERT_EQ(ply.status, 0) << ply.err;
    const MeshData m = load_mesh((dir / "out.ply").string());
    ASSERT_EQ(m.colors.size(), m.positions.size());
    ASSERT_EQ(m.triangles.size(), 2u);
    size_t matched = 0;
    for (size_t v = 0; v < m.positions.size(); ++v)
        for (const auto& [p, c] : want)
            if (m.positions[v] == p) {
                ++matched;
                for (int k = 0; k < 3; ++k)
                    EXPECT_NEAR(m.colors[v][k], std::round(255 * c[k]) / 255, 1e-6) << "vertex " << v << " channel " << k;
            }
    EXPECT_EQ(matched, m.positions.size());

    write_yaml_scene(dir, "view_point: [0, -20, 5], look_at: [0, 1, 0]", "{type: mesh, file: plain.obj, material: grey}");
    ASSERT_EQ(run_firsthit("export " + (dir / "scene.yaml").string() + " --quiet -o " + (dir / "plain_out.obj").string()).status, 0);
    std::ifstream plain(dir / "plain_out.obj");
    int vertices = 0;
    for (std::string line; std::getline(plain, line);)
        if (line.rfind("v ", 0) == 0) {
            ++vertices;
            EXPECT_EQ(std::count(line.begin(), line.end(), ' '), 3) << line;
        }
    EXPECT_EQ(vertices, 3);
}

// Placed in a scene file, a model is lit by that file's lights as the
// file's own surfaces are: glTF's materials have the report's ambient
// strength of 0.1. The model's triangle has glTF's default material (white,
// colour 255) and spans x 2..4, z 4..6 at y = -6; under the bunny scene's
// ambient light of 0.006 alone it is 0.006 x 0.1 x 255 x 255 = 39.0, as a
// YAML material of ambient 0.1 would be. (An ambient strength of 1 made it
// 390, clamped to 255: a model placed in the bunny's scene came out white.)
TEST(GltfCli, AModelInASceneFileIsLitByItsLightsAsItsOwnSurfaces) {
    const fs::path dir = model_dir("gltf_lit_by_yaml");
    std::ofstream(dir / "scene.yaml")
        << "lights:\n  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.006}\n"
           "cameras:\n  front: {type: perspective, width: 32, height: 32, view_point: [2.6, -20, 4.6], "
           "look_at: [0, 1, 0], up: [0, 0, 1], projection_distance: 10}\n"
           "surfaces:\n  - {type: gltf, name: model, file: model.gltf}\n";
    const auto r = run_firsthit("render " + (dir / "scene.yaml").string() + " -o " + (dir / "out.png").string());
    ASSERT_EQ(r.status, 0) << r.err;
    const Image image = read_png((dir / "out.png").string());
    ASSERT_EQ(image.width, 32);
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(image.pixel(16, 16)[ch], 39) << "channel " << ch;
}

// The glTF demo placed in a YAML scene and moved by a movie: its group by a
// surface path, its blob by a node path; no warning (its point light is a
// spot light without a cone, not a max_angle in degrees).
TEST(GltfCli, TheDemoInAYamlSceneAndMovie) {
    const fs::path dir = fresh_dir("gltf_demo_yaml");
    write_yaml_scene(dir, "view_point: [0, -20, 8], look_at: [0, 20, -8]",
                     "{type: gltf, name: demo, file: " + source_path("animations/gltf/demo.gltf") + "}");
    std::ofstream(dir / "movie.yaml")
        << "scene: scene.yaml\nfps: 10\nseconds: 2\nanimate:\n"
           "  surfaces.demo.transform.translate: {keyframes: [{frame: 0, value: [0, 0, 0]}, {frame: 20, value: [0, 0, 3]}]}\n"
           "  nodes.blob.scale: 2\n";
    for (const std::string file : {"scene.yaml", "movie.yaml"}) {
        const auto r = run_firsthit("render " + (dir / file).string() + " -o " + (dir / "out.png").string());
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err.rfind("wrote ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// A file placed in a scene file brings its cameras and lights named as its
// materials are, SURFACE/NAME: the demo placed twice beside a light of its
// own light's name once gave three lights named 'sun', of which a movie's
// `lights.sun` quietly moved one. Two unnamed placements would bring the
// same names again: an error at the second.
TEST(GltfCli, AFilePlacedTwiceNamesItsCamerasAndLightsByItsSurface) {
    const fs::path dir = fresh_dir("gltf_placed_twice");
    const std::string demo = source_path("animations/gltf/demo.gltf");
    const std::string head =
        "lights:\n  sun: {type: directional, color: [255, 255, 255], intensity: 0.5, direction: [0, 0, -1]}\n"
        "cameras:\n  c: {type: perspective, width: 32, height: 24, view_point: [0, -20, 8], look_at: [0, 20, -8], "
        "up: [0, 0, 1], projection_distance: 10}\nsurfaces:\n";
    std::ofstream(dir / "two.yaml") << head << "  - {type: gltf, name: a, file: " << demo << "}\n"
                                    << "  - {type: gltf, name: b, file: " << demo << ", transform: {translate: [3, 0, 0]}}\n";
    const auto info = run_firsthit("info " + (dir / "two.yaml").string());
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("\nlights: a/sun b/sun sun a/spot a/lamp b/spot b/lamp\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("\ncameras: c a/front b/front\n"), std::string::npos) << info.out;
    const auto picked = run_firsthit("render " + (dir / "two.yaml").string() + " --camera b/front -o " +
                                     (dir / "b.png").string());
    EXPECT_EQ(picked.status, 0) << picked.err;
    const auto bare = run_firsthit("render " + (dir / "two.yaml").string() + " --camera front -o " +
                                   (dir / "x.png").string());
    EXPECT_EQ(bare.status, 2);
    EXPECT_EQ(bare.err, "firsthit: error: no camera 'front' in " + (dir / "two.yaml").string() +
                            " (did you mean 'a/front'?)\n");

    // Its cameras may be all the scene has: no 'cameras:' key needed then.
    std::ofstream(dir / "no_cameras.yaml") << "surfaces:\n  - {type: gltf, name: a, file: " << demo << "}\n";
    const auto only = run_firsthit("info " + (dir / "no_cameras.yaml").string());
    ASSERT_EQ(only.status, 0) << only.err;
    EXPECT_NE(only.out.find("\ncameras: a/front\n"), std::string::npos) << only.out;

    std::ofstream(dir / "unnamed.yaml") << head << "  - {type: gltf, file: " << demo << "}\n"
                                        << "  - {type: gltf, file: " << demo << "}\n";
    const auto twice = run_firsthit("info " + (dir / "unnamed.yaml").string());
    EXPECT_EQ(twice.status, 2);
    EXPECT_EQ(twice.err, (dir / "unnamed.yaml").string() +
                             ":7:24: error: a second camera or light named 'gltf/front' (give each glTF surface a "
                             "name of its own)\n");
    EXPECT_EQ(twice.out, "");
}

// A .gltf names its default scene with a "scene" key, as the demo does; it
// is still a scene to a movie, not a movie of its own.
TEST(GltfCli, AGltfWithASceneKeyIsAMoviesScene) {
    const fs::path dir = fresh_dir("gltf_scene_key");
    const std::string demo = source_path("animations/gltf/demo.gltf");
    ASSERT_NE(slurp(demo).find("\"scene\""), std::string::npos);
    std::ofstream(dir / "movie.yaml") << "scene: " << demo << "\nfps: 10\nseconds: 1\nanimate:\n  nodes.blob.scale: 2\n";
    const auto r = run_firsthit("render " + (dir / "movie.yaml").string() + " --frame 3 --resolution 40x30 -o " +
                                (dir / "out.png").string());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "out.png"));
}

// A movie on the file at 10 fps: frame 5 is 0.5 s, where the file's own
// animation has base at (0,1.5,0). A path moves node "arm" from (1,2,3) to
// (1,2,5) over frames 0..10, so it is at (1,2,4):
//   (0,0,0) -> 2 (1,2,4) + (0,1.5,0) = (2,5.5,8) -> z-up (2,-8,5.5).
// A second path turns base a quarter turn about the file's y axis
// (x -> -z, z -> x): 2 R (1,2,4) = 2 (4,2,-1) = (8,4,-2), + (0,1.5,0) =
// (8,5.5,-2) -> z-up (8,2,5.5).
TEST(GltfCli, MovieNodePathsMoveTheFilesNodes) {
    const fs::path dir = model_dir("gltf_node_paths");
    const std::string head = "scene: model.gltf\nfps: 10\nseconds: 1\nanimate:\n";
    const std::string arm = "  nodes.arm.translation: {keyframes: [{frame: 0, value: [1, 2, 3]}, {frame: 10, value: [1, 2, 5]}]}\n";
    std::ofstream(dir / "movie.yaml") << head << arm;
    const auto v = exported((dir / "movie.yaml").string() + " --frame 5", dir);
    ASSERT_EQ(v.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[0][k], (dvec3{2, -8, 5.5})[k], 1e-9);
    const std::string half = std::to_string(kHalfSqrt2);
    std::ofstream(dir / "turn.yaml") << head << arm << "  nodes.base.rotation: [0, " << half << ", 0, " << half << "]\n";
    const auto turned = exported((dir / "turn.yaml").string() + " --frame 5", dir);
    ASSERT_EQ(turned.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned[0][k], (dvec3{8, 2, 5.5})[k], 1e-9);
}

TEST(GltfCli, NodePathMistakesAreOneLine) {
    const fs::path dir = model_dir("gltf_node_path_errors");
    auto error_of = [&](const std::string& animate) {
        std::ofstream(dir / "movie.yaml") << "scene: model.gltf\nfps: 10\nseconds: 1\nanimate:\n  " << animate << "\n";
        const auto r = run_firsthit("render " + (dir / "movie.yaml").string() + " -o " + (dir / "x.png").string());
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_FALSE(fs::exists(dir / "x.png"));
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        std::string line = r.err.substr(0, r.err.find('\n'));
        return line.replace(0, dir.string().size(), "DIR");
    };
    EXPECT_EQ(error_of("nodes.amr.translation: [0, 0, 0]"),
              "DIR/movie.yaml:5:3: error: no node named 'amr' in the scene's glTF files (did you mean 'arm'?)");
    EXPECT_EQ(error_of("nodes.arm.rotaton: [0, 0, 0, 1]"),
              "DIR/movie.yaml:5:3: error: unknown property 'rotaton' in 'nodes.arm.rotaton': a node can animate "
              "translation, rotation, scale (did you mean 'rotation'?)");
    EXPECT_EQ(error_of("nodes.arm.rotation: [0, 0, 1]"),
              "DIR/movie.yaml:5:23: error: 'nodes.arm.rotation' must be a quaternion [x, y, z, w], got a list");
    EXPECT_EQ(error_of("nodes.arm.rotation: [0, 0, 0, 0]"),
              "DIR/movie.yaml:5:23: error: 'nodes.arm.rotation' must not be the zero quaternion");
    EXPECT_EQ(error_of("nodes.arm.scale: [1, 0, 1]"),
              "DIR/movie.yaml:5:20: error: 'nodes.arm.scale' must not be 0 on any axis");
    EXPECT_EQ(error_of("nodes.arm.scale: {keyframes: [{frame: 0, value: 1}], interpolation: catmull_rom}"),
              "DIR/movie.yaml:5:71: error: unknown node interpolation 'catmull_rom' (expected step or linear)");
}

// 1 s of animation at 10 fps: frames 0..10, the last on the last key.
TEST(GltfCli, FramesRenderTheAnimationsLength) {
    const fs::path dir = model_dir("gltf_frames");
    const auto r = run_firsthit("frames " + (dir / "model.gltf").string() + " --fps 10 --resolution 24x24 --threads 2 --out " +
                                (dir / "frames").string());
    ASSERT_EQ(r.status, 0) << r.err;
    int pngs = 0;
    for (const auto& e : fs::directory_iterator(dir / "frames")) pngs += e.path().extension() == ".png";
    EXPECT_EQ(pngs, 11);
}

TEST(GltfCli, CameraByNameOrIndex) {
    const fs::path dir = model_dir("gltf_cameras");
    const std::string file = (dir / "model.gltf").string();
    auto render = [&](const std::string& camera, const std::string& out) {
        const auto r = run_firsthit("render " + file + " --camera '" + camera + "' --resolution 32x32 -o " +
                                    (dir / out).string());
        EXPECT_EQ(r.status, 0) << r.err;
        return slurp(dir / out);
    };
    EXPECT_EQ(render("far", "a.png"), render("1", "b.png"));
    EXPECT_EQ(render("near", "c.png"), render("0", "d.png"));
    EXPECT_NE(render("near", "c.png"), render("far", "a.png"));  // farther: a smaller triangle
    const auto r = run_firsthit("render " + file + " --camera fra -o " + (dir / "e.png").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "firsthit: error: no camera 'fra' in " + file + " (did you mean 'far'?); it has 0 'near', 1 'far'\n");
    EXPECT_FALSE(fs::exists(dir / "e.png"));
}

// Debian's simple_skin.gltf at frame 30 (1 s): joint 2 (under joint 1 at
// (0,1,0)) has turned 90 degrees about z (its key (0, 0, 0.707, 0.707),
// made unit). Both inverse bind matrices are T(-0.5,-1,0), so joint 1's
// matrix is T(-0.5,0,0) and joint 2's T(0,1,0) Rz(90) T(-0.5,-1,0):
//   vertex 1 (1,0,0), joint 1 alone:        (0.5, 0, 0)
//   vertex 5 (1,1,0), a half each: (0.5,1,0) and T(0,1,0) Rz (0.5,0,0) = (0,1.5,0) -> (0.25,1.25,0)
//   vertex 8 (0,2,0), joint 2: Rz (-0.5,1,0) = (-1,-0.5,0) -> (-1,0.5,0)
//   vertex 9 (1,2,0), joint 2: Rz (0.5,1,0) = (-1,0.5,0) -> (-1,1.5,0)
// z-up: (x, y, z) -> (x, -z, y). Export lists each triangle's corners in
// the file's index order (0 1 3, 0 3 2, 2 3 5, ..., 6 7 9, 6 9 8): vertex 1
// is written 2nd, 5 9th, 9 21st and 8 24th.
TEST(GltfCli, ExportOfDebiansSkinByHand) {
    const fs::path dir = fresh_dir("gltf_export_skin");
    const auto v = exported("/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf --frame 30", dir);
    ASSERT_EQ(v.size(), 24u);
    const std::pair<size_t, dvec3> want[] = {
        {1, {0.5, 0, 0}}, {8, {0.25, 0, 1.25}}, {20, {-1, 0, 1.5}}, {23, {-1, 0, 0.5}}};
    for (const auto& [at, p] : want)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[at][k], p[k], 1e-6) << "vertex " << at << " axis " << k;
    const auto info = run_firsthit("info /usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf");
    EXPECT_NE(info.out.find("\nskinned_meshes: 1\nmorphed_meshes: 0\ntextures: 0\ncutout_materials: 0\n"),
              std::string::npos)
        << info.out;
}

// The demo's floor tiles, their bevels and the trellis: three textures, one cutting the
// trellis out; and its glass pane, see-through.
TEST(GltfCli, InfoCountsTexturesCutoutsAndSeeThroughMaterials) {
    const auto info = run_firsthit("info " + source_path("animations/gltf/demo.gltf"));
    EXPECT_NE(info.out.find("\ntextures: 3\ncutout_materials: 1\nsee_through_materials: 1\n"), std::string::npos)
        << info.out;
}

// Debian's AnimatedMorphCube: one cube of 12 triangles, morphed, so its node
// traces its own copy and the rest pose is not traced. info counted both
// (24 distinct triangles, 12 shown).
TEST(GltfCli, InfoCountsAMorphedMeshOnce) {
    const auto info = run_firsthit(
        "info /usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("\ninstances: 1\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("\ndistinct_triangles: 12\ninstanced_triangles: 12\n"), std::string::npos) << info.out;
}

// Debian's AnimatedMorphCube.gltf at frame 60 (2 s, its key 60): weights
// (0.8055561, 0.1944439). Vertex 5 rests at (-0.01, -0.01, -0.01); the
// targets move its y by 0.0189325 and 0.0198908: y = -0.01 + 0.8055561 x
// 0.0189325 + 0.1944439 x 0.0198908 = 0.0091189. The node turns it 180
// degrees about (0, 1, -1) -- (x, y, z) -> (-x, -z, -y) -- and scales it
// 100: (1, 1, -0.91189); z-up: (1, 0.91189, 1). It is the 8th vertex
// written (triangle 6 5 4).
TEST(GltfCli, ExportOfDebiansMorphByHand) {
    const fs::path dir = fresh_dir("gltf_export_morph");
    const auto v = exported(
        "/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf --frame 60", dir);
    ASSERT_EQ(v.size(), 36u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[7][k], (dvec3{1, 0.91189, 1})[k], 2e-5) << "axis " << k;
    // Its bind pose (frame 0, weights 0): (-0.01,-0.01,-0.01) -> 100 (0.01,0.01,0.01) -> z-up (1,-1,1).
    const auto rest = exported(
        "/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf --frame 0", dir);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(rest[7][k], (dvec3{1, -1, 1})[k], 1e-5) << "axis " << k;
}

// A skinned movie's frames are a function of their index alone: one
// thread, three, shards and a resumed run give the same bytes (every frame
// deforms the mesh from its rest pose and refits the tree prepared once).
TEST(GltfCli, SkinnedFramesAreTheSameBytesForAnyThreadsShardsAndResume) {
    const fs::path dir = fresh_dir("gltf_skin_frames");
    const std::string skin = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf --fps 6 --resolution 48x36 --quiet";
    auto frames = [&](const std::string& out, const std::string& more) {
        const auto r = run_firsthit("frames " + skin + " --out " + (dir / out).string() + " " + more);
        ASSERT_EQ(r.status, 0) << r.err;
    };
    frames("one", "--threads 1");
    frames("three", "--threads 3");
    frames("shards", "--shard 0/2 --threads 2");
    frames("shards", "--shard 1/2 --threads 1");
    frames("resumed", "--range 10-20 --threads 2");
    frames("resumed", "--resume --threads 2");
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir / "one"))
        if (e.path().extension() == ".png") names.push_back(e.path().filename().string());
    ASSERT_EQ(names.size(), 34u);  // 5.5 s at 6 fps: frames 0 .. 33
    for (const std::string& folder : {"three", "shards", "resumed"})
        for (const std::string& n : names) EXPECT_EQ(slurp(dir / folder / n), slurp(dir / "one" / n)) << folder << "/" << n;
}

}  // namespace
}  // namespace fh::test
