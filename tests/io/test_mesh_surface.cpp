// A scene's `type: mesh` surfaces: the file found next to the scene file,
// its triangles transformed in the documented order (scale, rotate, then
// translate), and each mistake one error line naming the right file.
#include <gtest/gtest.h>

#include "io/input_error.h"
#include "io/scene_loader.h"
#include "io/scene_error.h"
#include "test_util.h"

namespace fh {
namespace {

using test::write_temp_file;

const std::string kHead =
    "materials:\n"
    "  grey: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
    "cameras:\n"
    "  c: {type: perspective, width: 8, height: 8, view_point: [0, -10, 0], look_at: [0, 1, 0], up: [0, 0, 1],\n"
    "      projection_distance: 10}\n";

// One triangle (1,0,0), (0,1,0), (0,0,1) and a degenerate one (a repeated
// vertex), as OFF next to the scenes.
void write_mesh() {
    write_temp_file("meshes/tri.off", "OFF\n4 2 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n3 0 1 2\n3 0 0 3\n");
}

void expect_near(const dvec3& got, const dvec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

TEST(MeshSurface, ScaledThenRotatedThenMovedByHand) {
    write_mesh();
    // (1,0,0): scale 2 -> (2,0,0); 90 degrees about z -> (0,2,0); +(1,2,3) -> (1,4,3).
    // (0,1,0): -> (0,2,0) -> (-2,0,0) -> (-1,2,3).  (0,0,1): -> (0,0,2) -> (0,0,2) -> (1,2,5).
    const Scene s = load_scene(write_temp_file("mesh_scene.yaml", kHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey,\n"
        "     transform: {scale: 2, rotate: {axis: [0, 0, 3], degrees: 90}, translate: [1, 2, 3]}}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 1u);
    expect_near(s.triangles[0].v0, {1, 4, 3});
    expect_near(s.triangles[0].v1, {-1, 2, 3});
    expect_near(s.triangles[0].v2, {1, 2, 5});
    // The face normal of the transformed triangle: (v1 - v0) x (v2 - v0), unit.
    expect_near(s.triangles[0].normal, glm::normalize(glm::cross(dvec3(-2, -2, 0), dvec3(0, -2, 2))));
    EXPECT_EQ(s.meshes, 1);
    EXPECT_EQ(s.degenerate_mesh_triangles, 1u);
}

TEST(MeshSurface, RadiansAndPerAxisScaleAndNoTransform) {
    write_mesh();
    const Scene s = load_scene(write_temp_file("mesh_radians.yaml", kHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey,\n"
        "     transform: {scale: [1, 2, 3], rotate: {axis: [1, 0, 0], radians: 3.141592653589793}}}\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 2u);
    // (0,1,0) -> (0,2,0) -> half a turn about x -> (0,-2,0); (0,0,1) -> (0,0,3) -> (0,0,-3).
    expect_near(s.triangles[0].v0, {1, 0, 0});
    expect_near(s.triangles[0].v1, {0, -2, 0});
    expect_near(s.triangles[0].v2, {0, 0, -3});
    expect_near(s.triangles[1].v1, {0, 1, 0});
}

TEST(MeshSurface, MistakesAreOneLineNamingTheirFile) {
    write_mesh();
    using test::scene_error;
    const std::string mesh = "  - {type: mesh, material: grey, ";
    EXPECT_EQ(scene_error(kHead + "surfaces:\n" + mesh + "file: meshes/tri.off, smooth: maybe}\n"),
              "FILE:7:64: error: expected true or false for 'smooth', got 'maybe'");
    EXPECT_EQ(scene_error(kHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {rotate: {axis: [0, 0, 1]}}}\n"),
              "FILE:7:76: error: 'rotate' needs an angle: 'degrees' or 'radians' (one of them)");
    EXPECT_EQ(scene_error(kHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {scale: 0}}\n"),
              "FILE:7:75: error: 'scale' must be > 0, got 0");
    EXPECT_EQ(scene_error(kHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {shear: 1}}\n"),
              "FILE:7:68: error: unknown key 'shear' in 'transform'");
    EXPECT_EQ(scene_error(kHead + "surfaces:\n" + mesh + "file: meshes/tri.off, smooth: true}\n"),
              "FILE:7:64: error: smooth shading of meshes is not supported yet; use smooth: false");
    // The mesh file's own errors name the mesh file, not the scene.
    const std::string scene = write_temp_file("missing_mesh.yaml", kHead + "surfaces:\n" + mesh + "file: meshes/none.off}\n");
    try {
        load_scene(scene);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), (std::filesystem::path(scene).parent_path() / "meshes/none.off").string());
        EXPECT_EQ(std::string(e.what()), "cannot open mesh file: no such file");
    }
}

}  // namespace
}  // namespace fh
