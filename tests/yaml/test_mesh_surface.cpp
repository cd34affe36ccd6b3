// A scene's `type: mesh` surfaces: the file found next to the scene file,
// its triangles transformed in the documented order (scale, rotate, then
// translate), and each mistake one error line naming the right file.
#include <gtest/gtest.h>

#include "text/input_error.h"
#include "render/packet_intersect.h"
#include "render/render.h"
#include "yaml/scene_loader.h"
#include "yaml/scene_error.h"
#include "support/expect_vec.h"
#include "test_util.h"

namespace fh {
namespace {

using test::expect_vec_near;
using test::write_temp_file;

const std::string kMeshHead =
    "materials:\n"
    "  grey: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
    "cameras:\n"
    "  c: {type: perspective, width: 8, height: 8, view_point: [0, -10, 0], look_at: [0, 1, 0], up: [0, 0, 1],\n"
    "      projection_distance: 10}\n";

// A roof of two triangles along the edge A = (0,0,0), B = (1,0,0):
// ABC with C = (0,1,0), face normal (0,0,1), |cross| = 1; and BAD with
// D = (0,-1,1), cross (A - B) x (D - B) = (0,1,1), |cross| = sqrt 2.
void write_roof() {
    write_temp_file("meshes/roof.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 1\n3 0 1 2\n3 1 0 3\n");
}

// One triangle (1,0,0), (0,1,0), (0,0,1) and a degenerate one (a repeated
// vertex), as OFF next to the scenes.
void write_mesh() {
    write_temp_file("meshes/tri.off", "OFF\n4 2 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n3 0 1 2\n3 0 0 3\n");
}

TEST(MeshSurface, ScaledThenRotatedThenMovedByHand) {
    write_mesh();
    // (1,0,0): scale 2 -> (2,0,0); 90 degrees about z -> (0,2,0); +(1,2,3) -> (1,4,3).
    // (0,1,0): -> (0,2,0) -> (-2,0,0) -> (-1,2,3).  (0,0,1): -> (0,0,2) -> (0,0,2) -> (1,2,5).
    const Scene s = load_scene(write_temp_file("mesh_scene.yaml", kMeshHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey,\n"
        "     transform: {scale: 2, rotate: {axis: [0, 0, 3], degrees: 90}, translate: [1, 2, 3]}}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 1u);
    expect_vec_near(s.triangles[0].v0, {1, 4, 3});
    expect_vec_near(s.triangles[0].v1, {-1, 2, 3});
    expect_vec_near(s.triangles[0].v2, {1, 2, 5});
    // The face normal of the transformed triangle: (v1 - v0) x (v2 - v0), unit.
    expect_vec_near(s.triangles[0].normal, glm::normalize(glm::cross(dvec3(-2, -2, 0), dvec3(0, -2, 2))));
    EXPECT_EQ(s.mesh_files, 1);
    EXPECT_EQ(s.degenerate_mesh_triangles, 1u);
}

TEST(MeshSurface, RadiansAndPerAxisScaleAndNoTransform) {
    write_mesh();
    const Scene s = load_scene(write_temp_file("mesh_radians.yaml", kMeshHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey,\n"
        "     transform: {scale: [1, 2, 3], rotate: {axis: [1, 0, 0], radians: 3.141592653589793}}}\n"
        "  - {type: mesh, file: meshes/tri.off, material: grey}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 2u);
    // (0,1,0) -> (0,2,0) -> half a turn about x -> (0,-2,0); (0,0,1) -> (0,0,3) -> (0,0,-3).
    expect_vec_near(s.triangles[0].v0, {1, 0, 0});
    expect_vec_near(s.triangles[0].v1, {0, -2, 0});
    expect_vec_near(s.triangles[0].v2, {0, 0, -3});
    expect_vec_near(s.triangles[1].v1, {0, 1, 0});
}

TEST(MeshSurface, MistakesAreOneLineNamingTheirFile) {
    write_mesh();
    using test::scene_error;
    const std::string mesh = "  - {type: mesh, material: grey, ";
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh + "file: meshes/tri.off, smooth: maybe}\n"),
              "FILE:7:64: error: expected true or false for 'smooth', got 'maybe'");
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {rotate: {axis: [0, 0, 1]}}}\n"),
              "FILE:7:76: error: 'rotate' needs an angle: 'degrees' or 'radians' (one of them)");
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh +
                          "file: meshes/tri.off, transform: {rotate: {axis: [0, 0, 1], degrees: 90, radians: 1}}}\n"),
              "FILE:7:76: error: 'rotate' gives its angle twice: 'degrees' or 'radians', not both");
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {scale: 0}}\n"),
              "FILE:7:75: error: 'scale' must not be 0 (a number, or one per axis; a negative one mirrors)");
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh + "file: meshes/tri.off, transform: {shear: 1}}\n"),
              "FILE:7:68: error: unknown key 'shear' in 'transform'");
    EXPECT_EQ(scene_error(kMeshHead + "surfaces:\n" + mesh + "name: a, file: meshes/tri.off}\n" +
                          "  - {type: sphere, name: a, center: [0, 0, 0], radius: 1, material: grey}\n"),
              "FILE:8:26: error: a second surface named 'a'");
    // The mesh file's own errors name the mesh file, not the scene.
    const std::string scene = write_temp_file("missing_mesh.yaml", kMeshHead + "surfaces:\n" + mesh + "file: meshes/none.off}\n");
    try {
        load_scene(scene);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), (std::filesystem::path(scene).parent_path() / "meshes/none.off").string());
        EXPECT_EQ(std::string(e.what()), "cannot open mesh file: no such file");
    }
}

TEST(MeshSurface, SmoothNormalsAreAreaWeightedByHand) {
    write_roof();
    const Scene s = load_scene(write_temp_file("roof_smooth.yaml", kMeshHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/roof.off, material: grey, smooth: true}\n"
        "  - {type: triangle, vertices: [[5, 5, 5], [6, 5, 5], [5, 6, 5]], material: grey}\n")).scene;
    ASSERT_EQ(s.triangles.size(), 3u);
    ASSERT_EQ(s.vertex_normals.size(), 3u);
    // A and B belong to both faces: (0,0,1) * 1 + (0,1,1)/sqrt2 * sqrt2 = (0,1,2), over sqrt 5.
    const dvec3 ab = dvec3(0, 1, 2) / std::sqrt(5.0);
    expect_vec_near(s.vertex_normals[0][0], ab);
    expect_vec_near(s.vertex_normals[0][1], ab);
    expect_vec_near(s.vertex_normals[0][2], {0, 0, 1});                      // C: ABC's alone
    expect_vec_near(s.vertex_normals[1][2], dvec3(0, 1, 1) / std::sqrt(2.0));  // D: BAD's alone
    EXPECT_EQ(s.vertex_normals[2][0], dvec3(0));  // the plain triangle is flat

    // Shading at ABC's centroid mixes its corners by 1/3 each; the face
    // normal, turned to the ray from above, stays (0,0,1).
    const auto g = FlatGeometry<double>::build(s);
    const Ray<double> down{{1.0 / 3, 1.0 / 3, 5}, {0, 0, -1}};
    const Hit<double> hit = closest_hit(g, down);
    ASSERT_TRUE(hit.found());
    const SurfacePoint<double> p = g.surface(down, hit);
    expect_vec_near(p.normal, {0, 0, 1});
    expect_vec_near(p.shading, glm::normalize(2.0 * ab + dvec3(0, 0, 1)));
    // The flat triangle shades with its face normal, facing the ray.
    const Ray<double> up{{5.25, 5.25, 0}, {0, 0, 1}};
    const SurfacePoint<double> q = g.surface(up, closest_hit(g, up));
    expect_vec_near(q.shading, {0, 0, -1});
    expect_vec_near(q.normal, {0, 0, -1});
}

TEST(MeshSurface, FileNormalsMoveByTheInverseTranspose) {
    write_temp_file("meshes/tri_vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nf 1//1 2//1 3//1\n");
    const Scene s = load_scene(write_temp_file("tri_vn.yaml", kMeshHead +
        "surfaces:\n"
        "  - {type: mesh, file: meshes/tri_vn.obj, material: grey, smooth: true, transform: {scale: [2, 1, 1]}}\n")).scene;
    ASSERT_EQ(s.vertex_normals.size(), 1u);
    // Stretching x by 2 tilts the normal (1,0,1) toward z: diag(1/2, 1, 1) (1,0,1) = (0.5, 0, 1).
    for (const dvec3& n : s.vertex_normals[0]) expect_vec_near(n, glm::normalize(dvec3(0.5, 0, 1)));
}

// A mesh file with vertex colours: they multiply the material's ambient
// and diffuse colours. Ambient light only (255 1/255 of the white
// material's ambient 1: 255 a channel), one triangle of colour (0.2, 0.4, 1)
// across the whole view: every pixel 255 times it.
TEST(MeshSurface, VertexColoursMultiplyTheMaterialsColours) {
    write_temp_file("meshes/colored.obj", "v -100 0 -100 0.2 0.4 1\nv 100 0 -100 0.2 0.4 1\nv 0 0 100 0.2 0.4 1\nf 1 2 3\n");
    const std::string scene =
        "materials:\n"
        "  white: {color: [255, 255, 255], ambient: 1, diffuse: 0, specular: 0, phong_exponent: 1}\n"
        "cameras:\n"
        "  c: {type: perspective, width: 8, height: 8, view_point: [0, -10, 0], look_at: [0, 1, 0], up: [0, 0, 1],\n"
        "      projection_distance: 10}\n"
        "lights:\n  a: {type: ambient, color: [255, 255, 255], intensity: 0.00392156862745098}\n"
        "effects: [ambient]\n"
        "surfaces:\n  - {type: mesh, name: m, file: meshes/colored.obj, material: white}\n";
    const auto loaded = load_scene(write_temp_file("colored_mesh.yaml", scene));
    // The world's triangles carry no colours: the file is a scene mesh and
    // the surface an instance of it, still named.
    EXPECT_TRUE(loaded.scene.triangles.empty());
    ASSERT_EQ(loaded.scene.instances.size(), 1u);
    ASSERT_NE(loaded.scene.find_surface("m"), nullptr);
    for (const Precision p : {Precision::float32, Precision::float64}) {
        RenderSettings settings = loaded.settings;
        settings.precision = p;
        const FrameResult r = render_frame(loaded.scene, loaded.scene.cameras[0], settings, nullptr);
        for (size_t i = 0; i < r.image.rgb.size(); i += 3) {
            EXPECT_EQ(int(r.image.rgb[i]), 51);
            EXPECT_EQ(int(r.image.rgb[i + 1]), 102);
            EXPECT_EQ(int(r.image.rgb[i + 2]), 255);
        }
    }
}

TEST(MeshSurface, SmoothRoofRendersFiniteAndShadesDifferently) {
    write_roof();
    const std::string head = kMeshHead + "lights:\n  sun: {type: directional, color: [255, 255, 255], intensity: 0.01,"
                                     " direction: [0.3, 0.2, -1]}\nsurfaces:\n";
    const auto flat = load_scene(write_temp_file("roof_flat.yaml", head +
        "  - {type: mesh, file: meshes/roof.off, material: grey, transform: {scale: 3}}\n"));
    const auto smooth = load_scene(write_temp_file("roof_smooth2.yaml", head +
        "  - {type: mesh, file: meshes/roof.off, material: grey, transform: {scale: 3}, smooth: true}\n"));
    Camera above = flat.scene.cameras[0];  // looking down on the roof
    above.width = above.height = 32;
    above.view_point = {1, 0, 10};
    above.look_at = {0, 0, -1};
    above.up = {0, 1, 0};
    const FrameResult a = render_frame(flat.scene, above, flat.settings, nullptr);
    const FrameResult b = render_frame(smooth.scene, above, smooth.settings, nullptr);
    EXPECT_EQ(a.counts.nonfinite_samples, 0u);
    EXPECT_EQ(b.counts.nonfinite_samples, 0u);
    EXPECT_NE(a.image.rgb, b.image.rgb);
}

}  // namespace
}  // namespace fh
