// The glTF loader (gltf/gltf_loader.h) on small files the tests write
// (gltf_builder.h): the node hierarchy, primitives and accessors, each
// expected value worked out by hand from the glTF 2.0 specification. A
// rotation written [0, 0, H, H] (H = sin 45°) is a quarter turn about z:
// x -> y, y -> -x.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf/gltf_load.h"

namespace fh {
namespace {

using namespace gltf_test;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// ---------------------------------------------------------------- hierarchy

TEST(GltfHierarchy, TrsChildOfAMatrixParentIsParentTimesTRS) {
    // Parent: scale 2 then move 10 along x. Child: T(1,2,3) R(90° about z) S(1,2,3):
    // R S has columns R(1,0,0) = (0,1,0), 2 R(0,1,0) = (-2,0,0), 3 R(0,0,1) = (0,0,3),
    // so the child is rows [0 -2 0 1; 1 0 0 2; 0 0 3 3], and parent x child
    // doubles that and adds 10 to the top right: [0 -4 0 12; 2 0 0 4; 0 0 6 6].
    Bin bin;
    const std::string json = gltf_json(triangle_mesh(bin) + R"(, "scenes": [{"nodes": [0]}], "nodes": [
        {"matrix": [2,0,0,0, 0,2,0,0, 0,0,2,0, 10,0,0,1], "children": [1]},
        {"mesh": 0, "translation": [1,2,3], "rotation": [0,0,0.7071067811865476,0.7071067811865476], "scale": [1,2,3]}])", bin);
    const GltfFile f = placed(json);
    ASSERT_EQ(f.scene.instances.size(), 1u);
    EXPECT_EQ(f.scene.instances[0].node, 1);
    const std::array<std::array<double, 4>, 4> want = {{{0, -4, 0, 12}, {2, 0, 0, 4}, {0, 0, 6, 6}, {0, 0, 0, 1}}};
    expect_matrix(f.scene.instances[0].to_world, want);
    expect_matrix(node_matrices(f.scene)[1], want);
    // The vertex (1,0,0): child (0,1,0) + (1,2,3) = (1,3,3), parent 2 (1,3,3) + (10,0,0).
    expect_vec(apply(f.scene.instances[0].to_world, {1, 0, 0}), {12, 6, 6});
}

TEST(GltfHierarchy, AMeshUsedByTwoNodesIsOneMeshAndTwoInstances) {
    Bin bin;
    const GltfFile f = placed(gltf_json(triangle_mesh(bin) + R"(, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0, "translation": [5,0,0]}, {"mesh": 0}])", bin));
    ASSERT_EQ(f.scene.meshes.size(), 1u);  // read once: no copy of the triangles
    ASSERT_EQ(f.scene.instances.size(), 2u);
    for (const int k : {0, 1}) {
        EXPECT_EQ(f.scene.instances[size_t(k)].mesh, 0);
        EXPECT_EQ(f.scene.instances[size_t(k)].node, k);
    }
    expect_vec(apply(f.scene.instances[0].to_world, {0, 0, 0}), {5, 0, 0});
    expect_vec(apply(f.scene.instances[1].to_world, {0, 0, 0}), {0, 0, 0});
}

TEST(GltfHierarchy, AChildListedBeforeItsParentStillComposesParentFirst) {
    // Node 1 (move 1 along x after a quarter turn about z) holds node 0
    // (move 1 along x). Parent of child: R(1,0,0) + (1,0,0) = (1,1,0); the
    // wrong order (child of parent) would give (2,0,0).
    Bin bin;
    const GltfFile f = placed(gltf_json(triangle_mesh(bin) + R"(, "scenes": [{"nodes": [1]}], "nodes": [
        {"mesh": 0, "translation": [1,0,0]},
        {"children": [0], "translation": [1,0,0], "rotation": [0,0,0.7071067811865476,0.7071067811865476]}])", bin));
    ASSERT_EQ(f.scene.nodes.size(), 2u);  // stored parents first
    EXPECT_EQ(f.scene.nodes[0].name, "node 1");
    EXPECT_EQ(f.scene.nodes[1].name, "node 0");
    EXPECT_EQ(f.scene.nodes[1].parent, 0);
    ASSERT_EQ(f.scene.instances.size(), 1u);
    expect_vec(apply(f.scene.instances[0].to_world, {0, 0, 0}), {1, 1, 0});
    // The vertex (1,0,0): child (2,0,0), turned (0,2,0), moved (1,2,0).
    expect_vec(apply(f.scene.instances[0].to_world, {1, 0, 0}), {1, 2, 0});
}

TEST(GltfHierarchy, AddGltfTurnsYUpToZUpInsideItsPlacement) {
    // +90° about x takes (x, y, z) to (x, -z, y); the placement (10 up) comes after.
    Bin bin;
    const Scene s = z_up(gltf_json(triangle_mesh(bin) + R"(, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": [1,2,3]}])", bin), Transform{dvec3(1), {0, 0, 1}, 0, {0, 0, 10}});
    ASSERT_EQ(s.instances.size(), 1u);
    expect_vec(apply(s.instances[0].to_world, {0, 0, 0}), {1, -3, 12});  // (1,2,3) -> (1,-3,2) -> +10 z
    expect_vec(apply(s.instances[0].to_world, {0, 1, 0}), {1, -3, 13});  // (1,3,3) -> (1,-3,3)
    ASSERT_EQ(s.groups.size(), 2u);  // the placement, and the turn inside it
    EXPECT_EQ(s.groups[1].parent, 0);
    EXPECT_EQ(s.nodes[0].group, 1);
}

TEST(GltfHierarchy, AddedTwiceEachCopyKeepsItsOwnIndices) {
    Bin bin;
    const std::string json = gltf_json(triangle_mesh(bin) + R"(, "materials": [{"name": "red"}],
        "scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"mesh": 0}])", bin);
    Scene s;
    add_gltf(s, load(json), "a", Transform{});
    add_gltf(s, load(json), "b", Transform{});
    // Each copy: 1 mesh, 2 materials (its own and the default), 2 nodes.
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[1].mesh, 1);
    EXPECT_EQ(s.instances[1].node, 3);
    EXPECT_EQ(s.nodes[3].parent, 2);
    EXPECT_EQ(s.material_names[3], "b/glTF default");
    EXPECT_EQ(s.instances[1].material, 3);  // the primitive has no material
}

TEST(GltfHierarchy, GpuInstancingRowsAreCopiesWithinTheNode) {
    // Row 0: T(1,0,0). Row 1: T(0,0,5) R(90° about y: x -> -z, z -> x) S(2):
    // rows [0 0 2; 0 2 0; -2 0 0] plus (0,0,5); the node adds (0,10,0) to both.
    Bin bin;
    const int t = bin.f32({1, 0, 0, 0, 0, 5}), r = bin.f32({0, 0, 0, 1, 0, 0.70710678f, 0, 0.70710678f}),
              sc = bin.f32({1, 1, 1, 2, 2, 2});
    const std::string more = ", " + accessor(t, kFloat, 2, "VEC3") + ", " + accessor(r, kFloat, 2, "VEC4") + ", " +
                             accessor(sc, kFloat, 2, "VEC3");
    const GltfFile f = placed(gltf_json(triangle_mesh(bin, more) + R"(, "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "translation": [0,10,0], "extensions":
        {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 1, "ROTATION": 2, "SCALE": 3}}}}])", bin));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    ASSERT_EQ(f.scene.instances.size(), 2u);
    expect_matrix(f.scene.instances[0].to_world, {{{1, 0, 0, 1}, {0, 1, 0, 10}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
    expect_matrix(f.scene.instances[1].to_world, {{{0, 0, 2, 0}, {0, 2, 0, 10}, {-2, 0, 0, 5}, {0, 0, 0, 1}}});
}

// --------------------------------------------------------------- primitives

TEST(GltfPrimitives, TrianglesIndexedAndNot) {
    Bin bin;
    const int square = bin.f32({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}), index = bin.u16({0, 1, 2, 0, 2, 3}),
              six = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}, "indices": 1}, {"attributes": {"POSITION": 2}})",
                                     accessor(square, kFloat, 4, "VEC3") + ", " + accessor(index, kUnsignedShort, 6, "SCALAR") +
                                         ", " + accessor(six, kFloat, 6, "VEC3")));
    ASSERT_EQ(f.scene.meshes.size(), 2u);  // one a primitive
    EXPECT_EQ(f.scene.meshes[0].mesh->triangles, (Triangles{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(f.scene.meshes[1].mesh->triangles, (Triangles{{0, 1, 2}, {3, 4, 5}}));
    EXPECT_EQ(f.scene.meshes[1].mesh->positions[4], dvec3(1, 0, 1));
    EXPECT_EQ(f.scene.instances.size(), 2u);
}

TEST(GltfPrimitives, StripsSwapTheFirstTwoOfEveryOtherTriangle) {
    // Specification 3.7.2.1: triangle i of a strip is (i, i + 1 + i%2, i + 2 - i%2),
    // so all face the same way: (0,1,2) (1,3,2) (2,3,4). Indexed [3,2,1,0]:
    // (3,2,1), then positions 1, 3, 2 of the list: (2,0,1).
    Bin bin;
    const int five = bin.f32({0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0}), index = bin.u8({3, 2, 1, 0});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}, "mode": 5},
                                              {"attributes": {"POSITION": 0}, "mode": 5, "indices": 1})",
                                     accessor(five, kFloat, 5, "VEC3") + ", " + accessor(index, kUnsignedByte, 4, "SCALAR")));
    ASSERT_EQ(f.scene.meshes.size(), 2u);
    EXPECT_EQ(f.scene.meshes[0].mesh->triangles, (Triangles{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}}));
    EXPECT_EQ(f.scene.meshes[1].mesh->triangles, (Triangles{{3, 2, 1}, {2, 0, 1}}));
}

TEST(GltfPrimitives, FansTurnAroundTheFirstVertex) {
    // Specification 3.7.2.1: triangle i of a fan is (i + 1, i + 2, 0).
    Bin bin;
    const int five = bin.f32({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}, "mode": 6})", accessor(five, kFloat, 5, "VEC3")));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    EXPECT_EQ(f.scene.meshes[0].mesh->triangles, (Triangles{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}}));
}

TEST(GltfPrimitives, PointsAndLinesAreSkippedWithOneWarningCountingThem) {
    // Points, lines, a line loop and a line strip beside a triangle; the mesh
    // is used by two nodes, and each primitive still counts once.
    Bin bin;
    const int tri = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), four = bin.f32({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    const GltfFile f = load(gltf_json(R"("scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0}, {"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}, {"attributes": {"POSITION": 1}, "mode": 0},
            {"attributes": {"POSITION": 1}, "mode": 1}, {"attributes": {"POSITION": 1}, "mode": 2},
            {"attributes": {"POSITION": 1}, "mode": 3}]}],
        "accessors": [)" + accessor(tri, kFloat, 3, "VEC3") + ", " + accessor(four, kFloat, 4, "VEC3") + "]", bin));
    EXPECT_EQ(f.scene.meshes.size(), 1u);
    EXPECT_EQ(f.scene.instances.size(), 2u);  // the triangle, by each node
    int skipped = 0;
    for (const std::string& w : f.warnings)
        if (w.find("points or lines") != std::string::npos) {
            ++skipped;
            EXPECT_EQ(w, "t.gltf: warning: 4 primitive(s) of points or lines skipped (triangles only)");
        }
    EXPECT_EQ(skipped, 1);
}

TEST(GltfPrimitives, TooFewVerticesForTheModeAreRefused) {
    // Triangles need a multiple of 3, strips and fans at least 3, lines a multiple of 2.
    Bin bin;
    const int four = bin.f32({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}), two = bin.f32({0, 0, 0, 1, 0, 0}),
              index = bin.u16({0, 1, 2, 3});
    const std::string accessors = accessor(four, kFloat, 4, "VEC3") + ", " + accessor(two, kFloat, 2, "VEC3") + ", " +
                                  accessor(index, kUnsignedShort, 2, "SCALAR") + ", " + accessor(four, kFloat, 3, "VEC3");
    auto refused = [&](const std::string& primitive, const std::string& phrase) {
        expect_input_error([&] { load(one_mesh(bin, primitive, accessors)); }, "t.gltf", phrase);
    };
    refused(R"({"attributes": {"POSITION": 0}})", "mesh 0 primitive 0: 4 vertices do not make whole triangles in mode 4");
    refused(R"({"attributes": {"POSITION": 1}, "mode": 5})", "2 vertices do not make whole triangles in mode 5");
    refused(R"({"attributes": {"POSITION": 0}, "mode": 6, "indices": 2})", "2 indices do not make whole triangles in mode 6");
    refused(R"({"attributes": {"POSITION": 3}, "mode": 1})", "3 vertices do not make whole lines in mode 1");
    refused(R"({"attributes": {"NORMAL": 0}})", "mesh 0 primitive 0: no POSITION attribute");
}

// ---------------------------------------------------------------- accessors

TEST(GltfAccessors, IndicesOfEveryUnsignedWidth) {
    // Read at the wrong width these would differ: the u16 bytes 00 00 02 00
    // 01 00 as bytes are 0, 0, 2; the u32 ones as shorts 1, 0, 0.
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), i8 = bin.u8({2, 1, 0}), i16 = bin.u16({0, 2, 1}),
              i32 = bin.u32({1, 0, 2});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}, "indices": 1},
            {"attributes": {"POSITION": 0}, "indices": 2}, {"attributes": {"POSITION": 0}, "indices": 3})",
        accessor(p, kFloat, 3, "VEC3") + ", " + accessor(i8, kUnsignedByte, 3, "SCALAR") + ", " +
            accessor(i16, kUnsignedShort, 3, "SCALAR") + ", " + accessor(i32, kUnsignedInt, 3, "SCALAR")));
    ASSERT_EQ(f.scene.meshes.size(), 3u);
    EXPECT_EQ(f.scene.meshes[0].mesh->triangles, (Triangles{{2, 1, 0}}));
    EXPECT_EQ(f.scene.meshes[1].mesh->triangles, (Triangles{{0, 2, 1}}));
    EXPECT_EQ(f.scene.meshes[2].mesh->triangles, (Triangles{{1, 0, 2}}));
}

TEST(GltfAccessors, InterleavedAttributesFollowTheByteStride) {
    // One view, stride 24: a position then a normal per vertex; NORMAL starts at byte 12.
    Bin bin;
    const int v = bin.f32({0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1, 0, 3, 0, 0, 1, 0}, 24);
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0, "NORMAL": 1}})",
                                     accessor(v, kFloat, 3, "VEC3") + ", " + accessor(v, kFloat, 3, "VEC3", ", \"byteOffset\": 12")));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    const Mesh& m = *f.scene.meshes[0].mesh;
    EXPECT_EQ(m.positions, (std::vector<dvec3>{{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}));
    EXPECT_EQ(m.normals, (std::vector<dvec3>{{0, 0, 1}, {0, 0, 1}, {0, 1, 0}}));
    EXPECT_TRUE(m.smooth);  // NORMALs make a primitive smooth
}

TEST(GltfAccessors, NormalizedAndPlainIntegersAsTheSpecificationMapsThem) {
    // KHR_mesh_quantization. Normalized u16 c -> c / 65535: 65535 -> 1,
    // 21845 -> 1/3, 13107 -> 0.2. Normalized i8 c -> max(c / 127, -1):
    // 127 -> 1, -128 -> -1, 64 -> 64/127. Plain i16: the numbers as they are.
    // Each element padded to 4 bytes (stride 8 and 4), as the specification asks.
    Bin bin;
    const int pos = bin.u16({0, 0, 0, 0, 65535, 0, 0, 0, 0, 21845, 13107, 0}, 8),
              nor = bin.i8({127, 0, 0, 0, 0, -128, 0, 0, 0, 64, -127, 0}, 4),
              plain = bin.i16({-3, 0, 0, 0, 0, 7, 0, 0, 0, 0, 300, 0}, 8);
    const GltfFile f = load(gltf_json(R"("extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}, {"attributes": {"POSITION": 2}}]}],
        "accessors": [)" + accessor(pos, kUnsignedShort, 3, "VEC3", ", \"normalized\": true") + ", " +
                                          accessor(nor, kByte, 3, "VEC3", ", \"normalized\": true") + ", " +
                                          accessor(plain, kShort, 3, "VEC3") + "]", bin));
    ASSERT_EQ(f.scene.meshes.size(), 2u);
    const Mesh& m = *f.scene.meshes[0].mesh;
    ASSERT_EQ(m.positions.size(), 3u);
    ASSERT_EQ(m.normals.size(), 3u);
    const dvec3 positions[] = {{0, 0, 0}, {1, 0, 0}, {0, 1.0 / 3, 0.2}}, normals[] = {{1, 0, 0}, {0, -1, 0}, {0, 64.0 / 127, -1}};
    for (size_t i = 0; i < 3; ++i) expect_vec(m.positions[i], positions[i]), expect_vec(m.normals[i], normals[i]);
    EXPECT_EQ(f.scene.meshes[1].mesh->positions, (std::vector<dvec3>{{-3, 0, 0}, {0, 7, 0}, {0, 0, 300}}));
}

TEST(GltfAccessors, SparseValuesReplaceTheirIndicesOfABufferView) {
    // Base (0,0,0) (1,0,0) (0,1,0); elements 0 and 2 replaced by (5,5,5) and (0,0,7).
    Bin bin;
    const int base = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), where = bin.u8({0, 2}), values = bin.f32({5, 5, 5, 0, 0, 7});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
                                     accessor(base, kFloat, 3, "VEC3", sparse(2, where, kUnsignedByte, values))));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    EXPECT_EQ(f.scene.meshes[0].mesh->positions, (std::vector<dvec3>{{5, 5, 5}, {1, 0, 0}, {0, 0, 7}}));
}

TEST(GltfAccessors, SparseWithoutABufferViewStartsFromZeros) {
    // Three zeros; elements 1 and 2 set to (1,0,0) and (0,1,0).
    Bin bin;
    const int where = bin.u16({1, 2}), values = bin.f32({1, 0, 0, 0, 1, 0});
    const GltfFile f = load(one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
        R"({"componentType": 5126, "count": 3, "type": "VEC3")" + sparse(2, where, kUnsignedShort, values) + "}"));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    EXPECT_EQ(f.scene.meshes[0].mesh->positions, (std::vector<dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

}  // namespace
}  // namespace fh
