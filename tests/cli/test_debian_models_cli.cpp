// An external suite: every glTF 2.0, OBJ, PLY, STL and OFF file of Debian's
// assimp-testmodels package (installed by scripts/setup.sh), rendered from
// the command line as a new user would. A file that should work renders a
// picture that shows it (not just the background); textures may be drawn
// untextured with one warning; every
// broken file is one `FILE: error: ...` line, exit status 2 and nothing
// written. The expected outcome of each file is in the tables below, so a
// file that starts or stops working fails the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "cli/run_command.h"
#include "support/png_read.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

struct Expected {
    const char* file;     // under kModels
    const char* outcome;  // "" renders; "warning: ..." renders with that warning; else the error's text
    const char* transform = "{}";  // mesh files: a `transform:` that brings it before the camera
};

// glTF2/: each file and what it should give.
const Expected kGltf[] = {
    {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", ""},
    {"glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", ""},
    {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", "warning: 1 texture(s) not drawn (emissive, occlusion, normal or metallic-roughness textures on other coordinates"},
    {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", ""},
    {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", ""},
    {"glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", ""},
    {"glTF2/BoxTextured-glTF/BoxTextured.gltf", ""},
    {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", ""},
    {"glTF2/cameras/Cameras.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", "warning: 1 primitive(s) of points or lines skipped"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_11.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_15.gltf", ""},
    {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", ""},
    {"glTF2/simple_skin/simple_skin.gltf", ""},
    {"glTF2/textureTransform/TextureTransformTest.gltf", ""},
    // The failure cases.
    {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "requires the extension KHR_technique_webgl"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "a value is not finite"},
    {"glTF2/IncorrectVertexArrays/Cube.gltf", "35 vertices do not make whole triangles"},
    {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "index 65535 is out of range (24 vertices)"},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "index 255 is out of range (24 vertices)"},
    {"glTF2/MissingBin/BoxTextured.gltf", "cannot find 'BoxTextured0.bin' beside the model"},
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "node 0 is its own ancestor (a cycle)"},
    {"glTF2/SchemaFailures/sceneWrongType.gltf", "scene: expected a whole number >= 0, got the string \"hello\""},
    {"glTF2/TestNoRootNode/NoScene.gltf", "the file has no scene to show"},
    {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "scene 0 has no nodes"},
    {"glTF2/draco/2CylinderEngine.gltf", "requires the extension KHR_draco_mesh_compression"},
    {"glTF2/issue_3269/texcoord_crash.gltf", "its material reads TEXCOORD_0, which it does not have"},
    {"glTF2/wrongTypes/badArray.gltf", "meshes[0].primitives: expected an array, got an object"},
    {"glTF2/wrongTypes/badExtension.gltf", "KHR_texture_transform: expected an object"},
    {"glTF2/wrongTypes/badNumber.gltf", "materials[0].normalTexture.index: required, and missing"},
    {"glTF2/wrongTypes/badObject.gltf", "materials[0].pbrMetallicRoughness: expected an object, got an array"},
    {"glTF2/wrongTypes/badString.gltf", "scenes[0].name: expected a string, got 42"},
    {"glTF2/wrongTypes/badUint.gltf", "baseColorTexture.index: expected a whole number >= 0, got -1"},
};

// glTF/: the same package's glTF 1.0 files, each refused as one: their
// first 1.0-shaped field ("scene": "defaultScene", a version of 1) once
// made the message.
const Expected kGltf1[] = {
    {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", "GLB version 1 (glTF 2.0 is version 2)"},
    {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", "a glTF 1.0 file (asset.version \"1.0\"): firsthit reads glTF 2.0"},
    {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", "a glTF 1.0 file (asset.version \"1.0\")"},
    {"glTF/BoxTextured-glTF/BoxTextured.gltf", "a glTF 1.0 file (asset.version \"1.0\")"},
    {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "a glTF 1.0 file (asset.version 1)"},
    {"glTF/IncorrectVertexArrays/Cube_v1.gltf", "a glTF 1.0 file (asset.version \"1.0\")"},
    {"glTF/TwoBoxes/TwoBoxes.gltf", "a glTF 1.0 file (asset.version \"1.0\")"},
};

// OBJ/, PLY/, STL/, OFF/: each mesh file and what it should give, placed
// as a `type: mesh` surface of a small scene.
const Expected kMeshFiles[] = {
    {"OBJ/WusonOBJ.obj", ""},
    {"OBJ/box.obj", ""},
    {"OBJ/box_UTF16BE.obj", "no triangles"},  // assimp 5.2.5's OBJ reader reads no UTF-16
    {"OBJ/box_longline.obj", ""},
    {"OBJ/box_mat_with_spaces.obj", ""},
    {"OBJ/box_without_lineending.obj", ""},
    {"OBJ/concave_polygon.obj", ""},
    {"OBJ/cube_mtllib_after_g.obj", ""},
    {"OBJ/cube_usemtl.obj", ""},
    {"OBJ/cube_with_vertexcolors.obj", ""},
    {"OBJ/cube_with_vertexcolors_uni.obj", ""},
    {"OBJ/empty_mat.obj", ""},
    {"OBJ/multiple_spaces.obj", ""},
    {"OBJ/number_formats.obj", "no triangles: 1 triangle, all of zero area"},
    {"OBJ/point_cloud.obj", "no triangles"},
    // 2,710 faces; assimp warns its UVs are 3-D. 1,600 units across.
    {"OBJ/regr01.obj", "", "{scale: 0.005, translate: [-3.1, -1.9, -0.8]}"},
    {"OBJ/regr_3429812.obj", ""},
    {"OBJ/space_in_material_name.obj", ""},
    {"OBJ/spider.obj", ""},
    {"OBJ/testline.obj", "no triangles, only points and lines"},
    {"OBJ/testmixed.obj", ""},
    {"OBJ/testpoints.obj", "no triangles, only points and lines"},
    {"OFF/Cube.off", ""},
    {"OFF/Wuson.off", ""},
    {"OFF/formatDetection", "unknown mesh format ''"},
    {"OFF/invalid.off", "a face with no vertices"},
    {"PLY/Wuson.ply", ""},
    {"PLY/cube.ply", ""},
    {"PLY/cube_binary.ply", ""},
    {"PLY/cube_uv.ply", ""},
    {"PLY/float-color.ply", ""},
    // Its face list was declared under the vertices: each vertex line lacks it.
    {"PLY/issue623.ply", ":13:56: error: a PLY line holds values for only 6 of its 7 properties"},
    {"PLY/points.ply", "no triangles"},
    {"PLY/pond.0.ply", "only 2171512 bytes follow it"},
    {"STL/3DSMaxExport.STL", ""},
    {"STL/Spider_ascii.stl", ""},
    {"STL/Spider_binary.stl", ""},
    {"STL/Wuson.stl", ""},
    {"STL/formatDetection", "unknown mesh format ''"},
    {"STL/sphereWithHole.stl", ""},
    {"STL/triangle.stl", ""},
    {"STL/triangle_with_empty_solid.stl", ""},  // one facet, then a solid with none
    {"STL/triangle_with_two_solids.stl", ""},
};

// Every file under `folder` whose name is one of `suffixes` (or, with an
// empty list, every file but pictures and material libraries).
std::set<std::string> files_under(const std::string& folder, const std::set<std::string>& suffixes) {
    std::set<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(kModels / folder)) {
        if (!e.is_regular_file()) continue;
        const std::string ext = e.path().extension().string();
        const bool wanted = suffixes.empty() ? ext != ".jpg" && ext != ".mtl" : suffixes.count(ext) > 0;
        if (wanted) out.insert(fs::relative(e.path(), kModels).string());
    }
    return out;
}

std::set<std::string> listed(const Expected* begin, const Expected* end) {
    std::set<std::string> out;
    for (const Expected* e = begin; e != end; ++e) out.insert(e->file);
    return out;
}

// Renders `target` (a model, or a scene naming `file`) and checks the
// outcome `expected` gives for `file`.
void check_model(const std::string& target, const std::string& file, const std::string& expected, const fs::path& png) {
    SCOPED_TRACE(file);
    const auto r = run_firsthit("render " + target + " -o " + png.string() + " --resolution 96x72 --threads 1");
    const std::string full = (kModels / file).string();
    const bool renders = expected.empty() || expected.starts_with("warning: ");
    if (renders) {
        ASSERT_EQ(r.status, 0) << r.err;
        const Image image = read_png(png.string());
        ASSERT_EQ(image.width, 96);
        // Something drawn: not every pixel the colour of the first.
        bool varies = false;
        for (std::size_t i = 3; i < image.rgb.size() && !varies; ++i) varies = image.rgb[i] != image.rgb[i % 3];
        EXPECT_TRUE(varies) << "a blank picture";
        // stderr: the warning, if any, then "wrote PATH ...".
        const std::string wrote = "wrote " + png.string();
        if (expected.empty()) {
            EXPECT_TRUE(r.err.starts_with(wrote)) << r.err;
        } else {
            // Each warning (a line of `expected`) on a line of its own, in order.
            std::string lines;
            for (size_t at = 0; at <= expected.size();) {
                const size_t end = std::min(expected.find('\n', at), expected.size());
                lines += full + ": " + expected.substr(at, end - at) + "\n";
                at = end + 1;
            }
            lines.pop_back();
            EXPECT_TRUE(r.err.starts_with(lines)) << r.err;
            EXPECT_NE(r.err.find("\n" + wrote), std::string::npos) << r.err;
        }
        const long warnings = expected.empty() ? 0 : 1 + std::count(expected.begin(), expected.end(), '\n');
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1 + warnings) << r.err;
    } else {
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_FALSE(fs::exists(png));
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        // FILE: error: ..., or FILE:LINE:COLUMN: error: ...
        EXPECT_TRUE(r.err.starts_with(full + ":")) << r.err;
        EXPECT_NE(r.err.find(": error: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    }
}

TEST(DebianModelsCli, TheTablesListEveryFile) {
    ASSERT_TRUE(fs::is_directory(kModels / "glTF2")) << "install Debian's assimp-testmodels (scripts/setup.sh does)";
    EXPECT_EQ(files_under("glTF2", {".gltf", ".glb"}), listed(std::begin(kGltf), std::end(kGltf)));
    EXPECT_EQ(files_under("glTF", {".gltf", ".glb"}), listed(std::begin(kGltf1), std::end(kGltf1)));
    std::set<std::string> meshes;
    for (const char* folder : {"OBJ", "PLY", "STL", "OFF"}) meshes.merge(files_under(folder, {}));
    EXPECT_EQ(meshes, listed(std::begin(kMeshFiles), std::end(kMeshFiles)));
}

TEST(DebianModelsCli, EveryGltfFileRendersOrIsOneLine) {
    const fs::path dir = fresh_dir("debian_gltf");
    int n = 0;
    for (const Expected& e : kGltf) {
        const fs::path png = dir / ("model" + std::to_string(n++) + ".png");
        check_model((kModels / e.file).string(), e.file, e.outcome, png);
    }
}

TEST(DebianModelsCli, EveryGltf1FileIsOneLineSayingSo) {
    const fs::path dir = fresh_dir("debian_gltf1");
    int n = 0;
    for (const Expected& e : kGltf1)
        check_model((kModels / e.file).string(), e.file, e.outcome, dir / ("model" + std::to_string(n++) + ".png"));
}

TEST(DebianModelsCli, EveryMeshFileRendersOrIsOneLine) {
    const fs::path dir = fresh_dir("debian_meshes");
    int n = 0;
    for (const Expected& e : kMeshFiles) {
        const fs::path scene = dir / ("scene" + std::to_string(n) + ".yaml");
        std::ofstream(scene) << "materials: {m: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, "
                                "phong_exponent: 1}}\n"
                                "surfaces:\n  - {type: mesh, file: '"
                             << (kModels / e.file).string()
                             << "', material: m, transform: " << e.transform << "}\n"
                                "lights: {a: {type: ambient, color: [255, 255, 255], intensity: 1}}\n"
                                "cameras: {c: {type: perspective, width: 96, height: 72, view_point: [0, -12, 6], "
                                "look_at: [0, 12, -6], up: [0, 0, 1], projection_distance: 10}}\n";
        check_model(scene.string(), e.file, e.outcome, dir / ("mesh" + std::to_string(n++) + ".png"));
    }
}

}  // namespace
}  // namespace fh::test
