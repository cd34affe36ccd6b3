// Many objects from the command line: instances, placements files and groups
// in scene files. Each mistake one line with exit status 2 and nothing
// written; groups composed as worked out by hand; an animated group or
// instance rendering the bytes of the static scene with that frame's values
// written in; an instanced scene the same picture as its copies written as
// type: mesh; and a movie of moving instances the same bytes for any thread
// count and shard layout.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cli/run_command.h"
#include "render/image_compare.h"
#include "support/off_file.h"
#include "support/png_read.h"
#include "yaml/scene_loader.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

const std::string kHead =
    "materials:\n"
    "  grey: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0.4, phong_exponent: 20}\n"
    "  red: {color: [220, 40, 30], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
    "  floor: {color: [140, 170, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
    "lights:\n"
    "  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.006}\n"
    "  sun: {type: directional, color: [255, 255, 255], intensity: 0.004, direction: [-1, 1, -2]}\n"
    "cameras:\n"
    "  front: {type: perspective, width: 96, height: 72, view_point: [0, -12, 6], look_at: [0, 12, -6],\n"
    "          up: [0, 0, 1], projection_distance: 10}\n";

// A folder with the ball, a placements file and scene.yaml = kHead + body.
fs::path scene_dir(const std::string& name, const std::string& body, const std::string& csv = "") {
    const fs::path dir = fresh_dir(name);
    write_icosphere_off(dir / "ball.off", 1);  // 80 triangles, closed
    if (!csv.empty()) std::ofstream(dir / "rows.csv") << csv;
    std::ofstream(dir / "scene.yaml") << kHead << body;
    return dir;
}

// The one error line a scene gives (exit status 2, nothing written), with
// the folder shown as DIR.
std::string error_of(const std::string& name, const std::string& body, const std::string& csv = "") {
    const fs::path dir = scene_dir(name, body, csv);
    const auto r = run_firsthit("render " + (dir / "scene.yaml").string() + " -o " + (dir / "out.png").string());
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    std::string line = r.err.substr(0, r.err.find('\n'));
    for (size_t at; (at = line.find(dir.string())) != std::string::npos;) line.replace(at, dir.string().size(), "DIR");
    return line;
}

const std::string kMeshes = "meshes:\n  ball: {file: ball.off}\n";

TEST(InstancesCli, EachMistakeIsOneLineAndNothingWritten) {
    // A set of instances placed by rows.csv (`more`: the set's other keys).
    auto rows_error = [](const std::string& name, const std::string& csv, const std::string& more = "") {
        return error_of(name, kMeshes + "surfaces:\n  - {type: instances, mesh: ball, material: grey, placements: rows.csv" +
                                  more + "}\n", csv);
    };
    // One instance of the ball with `more` keys.
    auto instance_error = [](const std::string& name, const std::string& more) {
        return error_of(name, kMeshes + "surfaces:\n  - {type: instance, mesh: ball, material: grey, " + more + "}\n");
    };
    EXPECT_EQ(error_of("bad_mesh_name", kMeshes + "surfaces:\n  - {type: instance, mesh: bal, material: grey}\n"),
              "DIR/scene.yaml:14:28: error: undefined mesh 'bal' (did you mean 'ball'?)");
    EXPECT_EQ(error_of("no_meshes", "surfaces:\n  - {type: instance, mesh: ball, material: grey}\n"),
              "DIR/scene.yaml:12:28: error: undefined mesh 'ball' (meshes are named in the scene's 'meshes:' section)");
    EXPECT_EQ(rows_error("short_row", "tx,ty,tz,scale\n0,0,0,1\n1,2\n"),
              "DIR/rows.csv:3:4: error: expected 4 values as the header names, got 2");
    EXPECT_EQ(rows_error("word_row", "tx,ty,tz\n0,0,0\n\n1,two,3\n"),
              "DIR/rows.csv:4:3: error: 'ty' must be a number, got 'two'");
    EXPECT_EQ(rows_error("inf_row", "tx, ty, tz\n0, 0, inf\n"),
              "DIR/rows.csv:2:7: error: 'tz' must be finite, got inf");
    EXPECT_EQ(rows_error("zero_row", "scale,tx,ty,tz\n0,1,2,3\n"),
              "DIR/rows.csv:2:1: error: 'scale' must not be 0");
    EXPECT_EQ(rows_error("bad_column", "tx,ty,tz,scael\n0,1,2,3\n"),
              "DIR/rows.csv:1:10: error: unknown column 'scael' (did you mean 'scale'?); the columns are tx, ty, "
              "tz, scale, axis_x, axis_y, axis_z, degrees");
    EXPECT_EQ(instance_error("zero_scale", "transform: {scale: [1, 0, 1]}"),
              "DIR/scene.yaml:14:69: error: 'scale' must not be 0 (a number, or one per axis; a negative one mirrors)");
    EXPECT_EQ(instance_error("nan_scale", "transform: {scale: .nan}"),
              "DIR/scene.yaml:14:69: error: 'scale' must be finite");
    // Fine alone, too small together: 1e-7 x 1e-7 is past the 1e-12 limit.
    EXPECT_EQ(error_of("too_small", kMeshes + "surfaces:\n  - {type: group, transform: {scale: 1e-7}, surfaces: "
                                              "[{type: instance, mesh: ball, material: grey, transform: {scale: 1e-7}}]}\n"),
              "DIR/scene.yaml:14:112: error: the transform scales by 1e-14 along an axis; the limit is 1e-12 to 1e12");
    EXPECT_EQ(error_of("too_large", kMeshes + "surfaces:\n  - {type: group, transform: {scale: 1e60}, surfaces: "
                                              "[{type: instance, mesh: ball, material: grey}]}\n"),
              "DIR/scene.yaml:14:30: error: the transform scales by 1e+60 along an axis; the limit is 1e-12 to 1e12");
    // A mesh placed in the world is checked as well as one in a group.
    EXPECT_EQ(error_of("world_mesh", "surfaces:\n  - {type: mesh, file: ball.off, material: grey, "
                                     "transform: {scale: 1e-200}}\n"),
              "DIR/scene.yaml:12:61: error: the transform scales by 1e-200 along an axis; the limit is 1e-12 to 1e12");
    // A row that is fine alone but not under its set's transform: its own line.
    EXPECT_EQ(rows_error("placed_row", "tx,ty,tz,scale\n0,0,0,1\n\n1,2,3,1e-7\n", ", transform: {scale: 1e-6}"),
              "DIR/rows.csv:4:1: error: the transform scales by 1e-13 along an axis; the limit is 1e-12 to 1e12 "
              "(the row placed by its set and groups)");
    EXPECT_EQ(rows_error("huge_row", "tx,ty,tz\n0,0,+1e999\n"),
              "DIR/rows.csv:2:5: error: 'tz' must be finite, got +1e999");
    EXPECT_EQ(error_of("far_name", kMeshes + "surfaces:\n  - {type: instance, mesh: zzzzzz, material: grey}\n"),
              "DIR/scene.yaml:14:28: error: undefined mesh 'zzzzzz' (the scene's meshes: ball)");
    EXPECT_EQ(error_of("twice", kMeshes + "surfaces:\n  - {type: instance, name: a, mesh: ball, material: grey}\n"
                                          "  - {type: group, name: a}\n"),
              "DIR/scene.yaml:15:25: error: a second surface named 'a'");
    EXPECT_EQ(error_of("uneven_sphere", "surfaces:\n  - {type: group, transform: {scale: [1, 2, 1]}, surfaces: "
                                        "[{type: sphere, center: [0, 0, 0], radius: 1, material: red}]}\n"),
              "DIR/scene.yaml:12:61: error: a sphere in a group scaled unevenly would be an ellipsoid: scale the "
              "group (and those around it) by one number");
}

// A spreadsheet's CSV: a byte order mark, '+' signs, numbers too small for
// a double (0); each row as written.
TEST(InstancesCli, PlacementsAsSpreadsheetsWriteThem) {
    const fs::path dir = scene_dir("spreadsheet_rows", kMeshes + "surfaces:\n  - {type: instances, mesh: ball, "
                                   "material: grey, placements: rows.csv}\n",
                                   "\xEF\xBB\xBFtx,ty,tz,scale\n+1,-2,+3e0,+0.5\n1e-999,0,0,1\n");
    const Scene s = load_scene((dir / "scene.yaml").string()).scene;
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(dvec3(s.instances[0].to_world[3]), dvec3(1, -2, 3));
    EXPECT_EQ(s.instances[0].to_world[0][0], 0.5);
    EXPECT_EQ(dvec3(s.instances[1].to_world[3]), dvec3(0, 0, 0));
    // Lines ended by CR LF, or by a lone CR ("CSV (Macintosh)", which once
    // read as one line: "unknown column 'tz\x0d1'"); a mistake keeps its line.
    for (const std::string eol : {"\r\n", "\r"}) {
        std::ofstream(dir / "rows.csv") << "tx,ty,tz" << eol << "1,2,3" << eol << eol << "4,5,6" << eol;
        const Scene t = load_scene((dir / "scene.yaml").string()).scene;
        ASSERT_EQ(t.instances.size(), 2u);
        EXPECT_EQ(dvec3(t.instances[1].to_world[3]), dvec3(4, 5, 6));
        std::ofstream(dir / "rows.csv") << "tx,ty,tz" << eol << "1,2,3" << eol << "4,5" << eol;
        try {
            load_scene((dir / "scene.yaml").string());
            ADD_FAILURE() << "a short row was read";
        } catch (const InputError& e) {
            EXPECT_EQ(e.line(), 3);
        }
    }
}

// A file named by 'meshes:' and by a type: mesh surface is read once.
TEST(InstancesCli, AMeshFileIsReadOnceWhateverNamesIt) {
    const fs::path dir = scene_dir("mesh_read_once", kMeshes + "surfaces:\n  - {type: instance, mesh: ball, material: grey}\n"
                                   "  - {type: mesh, file: ball.off, material: red}\n");
    const Scene s = load_scene((dir / "scene.yaml").string()).scene;
    EXPECT_EQ(s.mesh_files, 1);
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.triangles.size(), 80u);
}

// A movie may not scale a group holding a sphere unevenly (the scene may
// not either); evenly, or a group without spheres, it may.
TEST(InstancesCli, AMovieScalesAGroupWithASphereEvenly) {
    const fs::path dir = scene_dir("movie_sphere_scale", kMeshes + "surfaces:\n"
        "  - {type: group, name: g, surfaces: [{type: group, surfaces: [{type: sphere, center: [0, 0, 0], radius: 1, material: red}]}]}\n"
        "  - {type: group, name: h, surfaces: [{type: instance, mesh: ball, material: grey}]}\n");
    auto run = [&](const std::string& animate) {
        std::ofstream(dir / "movie.yaml") << "scene: scene.yaml\nfps: 10\nseconds: 1\nanimate:\n  " << animate << "\n";
        fs::remove(dir / "x.png");
        return run_firsthit("render " + (dir / "movie.yaml").string() + " --frame 5 -o " + (dir / "x.png").string());
    };
    const auto uneven = run("surfaces.g.transform.scale: {keyframes: [{frame: 0, value: 1}, {frame: 9, value: [1, 4, 1]}]}");
    EXPECT_EQ(uneven.status, 2);
    EXPECT_EQ(uneven.err, (dir / "movie.yaml").string() + ":5:31: error: 'surfaces.g.transform.scale' must scale by one "
                          "number: group 'g' holds a sphere, which an uneven scale would make an ellipsoid\n");
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    EXPECT_EQ(run("surfaces.g.transform.scale: {keyframes: [{frame: 0, value: 1}, {frame: 9, value: [4, 4, 4]}]}").status, 0);
    EXPECT_EQ(run("surfaces.h.transform.scale: [1, 4, 1]").status, 0);
}

// Nested groups, placed as worked out by hand: a group moved by (10, 0, 0)
// and turned 90 degrees about z holds a group scaled by 2 holding an
// instance moved by (1, 0, 0), a sphere and a triangle.
TEST(InstancesCli, GroupsComposeTheirTransformsOutwards) {
    const fs::path dir = scene_dir("groups_by_hand", kMeshes +
        "surfaces:\n"
        "  - {type: group, name: outer, transform: {rotate: {axis: [0, 0, 1], degrees: 90}, translate: [10, 0, 0]},\n"
        "     surfaces: [{type: group, name: inner, transform: {scale: 2}, surfaces: [\n"
        "       {type: instance, name: b, mesh: ball, material: grey, transform: {translate: [1, 0, 0]}},\n"
        "       {type: sphere, name: s, center: [0, 1, 0], radius: 0.5, material: red},\n"
        "       {type: triangle, vertices: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], material: red}]}]}\n");
    const Scene s = load_scene((dir / "scene.yaml").string()).scene;
    ASSERT_EQ(s.instances.size(), 1u);
    ASSERT_EQ(s.groups.size(), 2u);
    EXPECT_EQ(s.groups[1].parent, 0);
    // p -> R90(2 (p + (1, 0, 0))) + (10, 0, 0): the origin goes to (10, 2, 0),
    // (1, 0, 0) to (10, 4, 0), (0, 1, 0) to (8, 2, 0).
    const glm::dmat4& m = s.instances[0].to_world;
    auto placed = [&](dvec3 p) { return dvec3(m * glm::dvec4(p, 1.0)); };
    auto near = [](dvec3 a, dvec3 b) { return glm::length(a - b) < 1e-12; };
    EXPECT_TRUE(near(placed({0, 0, 0}), {10, 2, 0}));
    EXPECT_TRUE(near(placed({1, 0, 0}), {10, 4, 0}));
    EXPECT_TRUE(near(placed({0, 1, 0}), {8, 2, 0}));
    // The sphere: centre (0, 1, 0) -> R90(0, 2, 0) + (10, 0, 0) = (8, 0, 0); radius 2 x 0.5.
    EXPECT_TRUE(near(s.spheres()[0].center, {8, 0, 0}));
    EXPECT_NEAR(s.spheres()[0].radius, 1.0, 1e-12);
    // The triangle's corners: (1,0,0) -> (10,2,0); (0,1,0) -> (8,0,0); (0,0,1) -> (10,0,2).
    EXPECT_TRUE(near(s.triangles[0].v0, {10, 2, 0}));
    EXPECT_TRUE(near(s.triangles[0].v1, {8, 0, 0}));
    EXPECT_TRUE(near(s.triangles[0].v2, {10, 0, 2}));
}

fs::path render_placed(const fs::path& file, const std::string& extra, const std::string& out_name) {
    const fs::path out = file.parent_path() / out_name;
    const auto r = run_firsthit("render " + file.string() + " " + extra + " --quiet -o " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
}

const std::string kAnimatedScene = kMeshes +
    "surfaces:\n"
    "  - {type: plane, normal: [0, 0, 1], distance: -1, material: floor}\n"
    "  - {type: group, name: cart, transform: {translate: [-2, 0, 0]}, surfaces: [\n"
    "      {type: instance, name: wheel, mesh: ball, material: grey, transform: {translate: [0, 1, 0]}},\n"
    "      {type: sphere, center: [0, -1, 0], radius: 0.8, material: red},\n"
    "      {type: mesh, file: ball.off, material: grey, transform: {scale: 0.5, translate: [0, 0, 1.5]}}]}\n"
    "  - {type: instance, name: lone, mesh: ball, material: red, transform: {translate: [3, 0, 0]}}\n";

// A movie moving the group and one instance: frame 10 is the static scene
// with frame 10's values written in, to the byte.
TEST(InstancesCli, AnimatedGroupsAndInstancesAreTheStaticSceneAtEachKey) {
    const fs::path dir = scene_dir("animated_groups", kAnimatedScene);
    std::ofstream(dir / "movie.yaml")
        << "scene: scene.yaml\ncamera: front\nfps: 10\nseconds: 2\nanimate:\n"
           "  surfaces.cart.transform.translate: {keyframes: [{frame: 0, value: [-2, 0, 0]}, {frame: 10, value: [1, 2, 0.5]}]}\n"
           "  surfaces.cart.transform.rotate.axis: [0, 0, 1]\n"
           "  surfaces.cart.transform.rotate.degrees: {keyframes: [{frame: 0, value: 0}, {frame: 10, value: 30}]}\n"
           "  surfaces.lone.transform.scale: {keyframes: [{frame: 0, value: 1}, {frame: 10, value: [1, 2, -0.5]}]}\n";
    std::string moved = kAnimatedScene;
    moved.replace(moved.find("transform: {translate: [-2, 0, 0]}"), 34,
                  "transform: {translate: [1, 2, 0.5], rotate: {axis: [0, 0, 1], degrees: 30}}");
    moved.replace(moved.find("transform: {translate: [3, 0, 0]}"), 33,
                  "transform: {translate: [3, 0, 0], scale: [1, 2, -0.5]}");
    std::ofstream(dir / "moved.yaml") << kHead << moved;
    const fs::path frame10 = render_placed(dir / "movie.yaml", "--frame 10", "frame10.png");
    const fs::path still = render_placed(dir / "moved.yaml", "", "still.png");
    EXPECT_EQ(slurp(frame10), slurp(still));
    // Frame 0 is the file's scene, and the movie did move things.
    EXPECT_EQ(slurp(render_placed(dir / "movie.yaml", "--frame 0", "frame0.png")), slurp(render_placed(dir / "scene.yaml", "", "s.png")));
    EXPECT_NE(slurp(frame10), slurp(dir / "s.png"));
}

// Twelve copies as instances and as type: mesh surfaces: the same picture
// but for rounding (the instances' triangles are tested in their own space).
TEST(InstancesCli, InstancesLookLikeTheirCopiesAsMeshes) {
    std::string instances = kMeshes + "surfaces:\n  - {type: plane, normal: [0, 0, 1], distance: -1, material: floor}\n";
    std::string meshes = "surfaces:\n  - {type: plane, normal: [0, 0, 1], distance: -1, material: floor}\n";
    for (int i = 0; i < 12; ++i) {
        const std::string t = "transform: {scale: [" + std::to_string(0.6 + 0.05 * i) + ", 0.8, " +
                              (i % 2 ? "-" : "") + "0.7], rotate: {axis: [1, 1, " + std::to_string(i) +
                              "], degrees: " + std::to_string(17 * i) + "}, translate: [" +
                              std::to_string(-6 + 1.1 * i) + ", " + std::to_string(i % 3) + ", 0]}";
        instances += "  - {type: instance, mesh: ball, material: grey, " + t + "}\n";
        meshes += "  - {type: mesh, file: ball.off, material: grey, smooth: false, " + t + "}\n";
    }
    const fs::path dir = scene_dir("instances_vs_meshes", instances);
    std::ofstream(dir / "meshes.yaml") << kHead << meshes;
    for (const char* precision : {"float", "double"}) {
        const std::string flags = std::string("--precision ") + precision + " --resolution 400x300";
        const Image a = read_png(render_placed(dir / "scene.yaml", flags, "a.png").string());
        const Image b = read_png(render_placed(dir / "meshes.yaml", flags, "b.png").string());
        ASSERT_GT(a.width, 0);
        // At most 0.1% of the pixels with any channel off.
        const ImageError e = compare_images(a, b);
        EXPECT_LE(e.differing, 0.001) << precision << ": " << e.differing * 400 * 300 << " pixels";
    }
}

// Moving instances in a movie: the same bytes for any --threads, shards and
// --resume, and each frame of `frames` (every frame's set from the one before
// it, refitted -- or, from frame 7 on, where the keys hold, kept) is the
// frame `render --frame` builds afresh.
TEST(InstancesCli, MovingInstancesAreTheSameBytesForAnyThreadsShardsAndResume) {
    const fs::path dir = scene_dir("instances_determinism", kAnimatedScene);
    std::ofstream(dir / "movie.yaml")
        << "scene: scene.yaml\ncamera: front\nfps: 4\nseconds: 2.5\nanimate:\n"
           "  surfaces.cart.transform.rotate.axis: [0, 0, 1]\n"
           "  surfaces.cart.transform.rotate.degrees: {keyframes: [{frame: 0, value: 0}, {frame: 7, value: 90}]}\n"
           "  surfaces.wheel.transform.translate: {keyframes: [{frame: 0, value: [0, 1, 0]}, {frame: 7, value: [0, 2, 1]}]}\n";
    auto frames = [&](const std::string& out, const std::string& extra) {
        const auto r = run_firsthit("frames " + (dir / "movie.yaml").string() + " --quiet --out " +
                                    (dir / out).string() + " " + extra);
        ASSERT_EQ(r.status, 0) << r.err;
    };
    frames("ref", "--threads 1");
    frames("threads", "--threads 3");
    for (int k = 0; k < 3; ++k) frames("shards", "--shard " + std::to_string(k) + "/3 --threads 2");
    frames("resumed", "--threads 2");
    fs::remove(dir / "resumed" / "frame_0003.png");
    fs::remove(dir / "resumed" / "frame_0008.png");
    fs::resize_file(dir / "resumed" / "frame_0005.png", 100);
    frames("resumed", "--resume --threads 2");
    for (int i = 0; i < 10; ++i) {
        const std::string name = "frame_000" + std::to_string(i) + ".png";
        const std::string ref = slurp(dir / "ref" / name);
        ASSERT_FALSE(ref.empty()) << name;
        EXPECT_EQ(slurp(dir / "threads" / name), ref) << name;
        EXPECT_EQ(slurp(dir / "shards" / name), ref) << name;
        EXPECT_EQ(slurp(dir / "resumed" / name), ref) << name;
        EXPECT_EQ(slurp(render_placed(dir / "movie.yaml", "--frame " + std::to_string(i), "one.png")), ref) << name;
    }
    EXPECT_NE(slurp(dir / "ref" / "frame_0000.png"), slurp(dir / "ref" / "frame_0007.png"));
    EXPECT_EQ(slurp(dir / "ref" / "frame_0007.png"), slurp(dir / "ref" / "frame_0009.png"));
}

}  // namespace
}  // namespace fh::test
