// Morph targets and skins (scene/deformation.h) on one triangle, worked out
// by hand at, between and beyond keys; and bad ones, one line each.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "anim/node_channel.h"
#include "gltf/gltf_load.h"

namespace fh {
namespace {

using namespace gltf_test;

// Deformation d's vertices in the world (placed by its instance).
std::vector<dvec3> world_of(const Scene& s, size_t d) {
    const int mesh = s.deformations[d].mesh;
    for (const Instance& i : s.instances)
        if (i.mesh == mesh) {
            std::vector<dvec3> out;
            for (const dvec3& p : s.meshes[size_t(mesh)].mesh->positions) out.push_back(apply(i.to_world, p));
            return out;
        }
    ADD_FAILURE() << "no instance places deformation " << d;
    return {};
}

// The file's channels at time t, and the meshes deformed to match.
void pose_at(Scene& s, const std::vector<NodeAnimation>& animations, double t) {
    apply_channels(animations[0].channels, t, s);
    place_nodes(s);
    deform_meshes(s);
}

void expect_points(const std::vector<dvec3>& got, const std::vector<dvec3>& want, const std::string& when,
                   double tolerance = 1e-12) {
    ASSERT_EQ(got.size(), want.size()) << when;
    for (size_t v = 0; v < got.size(); ++v)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[v][k], want[v][k], tolerance) << when << ": vertex " << v << " axis " << k;
}

// The triangle (0,0,0) (1,0,0) (0,1,0) with two targets: T0 lifts vertex 0
// by (0,0,1), T1 moves vertex 1 by (1,0,0). Node 0 uses the mesh's weights
// (0.5, 0); node 1 its own (0, 1). Both animate their weights from (0, 0)
// at 0 s to (1, 2) at 2 s: node 0 LINEAR, node 1 STEP.
std::string morphed_file() {
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), t0 = bin.f32({0, 0, 1, 0, 0, 0, 0, 0, 0}),
              t1 = bin.f32({0, 0, 0, 1, 0, 0, 0, 0, 0}), times = bin.f32({0, 2}), w = bin.f32({0, 0, 1, 2});
    return gltf_json(R"("scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0}, {"mesh": 0, "weights": [0, 1]}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}, {"POSITION": 2}]}],
            "weights": [0.5, 0]}],
"accessors": [)" + joined({accessor(p, kFloat, 3, "VEC3"), accessor(t0, kFloat, 3, "VEC3"),
                           accessor(t1, kFloat, 3, "VEC3"), accessor(times, kFloat, 2, "SCALAR"),
                           accessor(w, kFloat, 4, "SCALAR")}) + "], " +
                         animation(joined({channel(0, 0, "weights"), channel(1, 1, "weights")}),
                                   joined({sampler(3, 4, "LINEAR"), sampler(3, 4, "STEP")})),
                     bin);
}

TEST(GltfMorph, ATriangleByHandAtBetweenAndBeyondKeys) {
    GltfFile file = load(morphed_file());
    Scene s;
    const std::vector<NodeAnimation> animations = add_gltf(s, std::move(file), "m", Transform{});
    ASSERT_EQ(s.deformations.size(), 2u);  // each node its own copy
    // Positions in the nodes' own (file) space: no node moves here.
    auto mesh = [&](size_t d) { return s.meshes[size_t(s.deformations[d].mesh)].mesh->positions; };
    // As loaded: node 0 at (0.5, 0) lifts vertex 0 by 0.5; node 1 at (0, 1) moves vertex 1 to x = 2.
    expect_points(mesh(0), {{0, 0, 0.5}, {1, 0, 0}, {0, 1, 0}}, "loaded, node 0");
    expect_points(mesh(1), {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, "loaded, node 1");
    // t = 0: both (0, 0), the rest pose.
    pose_at(s, animations, 0);
    expect_points(mesh(0), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "t = 0");
    // t = 1: LINEAR halfway, (0.5, 1); STEP still (0, 0).
    pose_at(s, animations, 1);
    expect_points(mesh(0), {{0, 0, 0.5}, {2, 0, 0}, {0, 1, 0}}, "t = 1, linear");
    expect_points(mesh(1), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "t = 1, step");
    // t = 2 and beyond: (1, 2) held.
    for (const double t : {2.0, 5.0}) {
        pose_at(s, animations, t);
        expect_points(mesh(0), {{0, 0, 1}, {3, 0, 0}, {0, 1, 0}}, "t = " + std::to_string(t));
        expect_points(mesh(1), {{0, 0, 1}, {3, 0, 0}, {0, 1, 0}}, "t = " + std::to_string(t));
    }
}

// Node 0 holds the mesh at (5,0,0) -- which a skin ignores -- and joint A
// (node 1, at the origin) holds joint B (node 2, at (0,1,0)); B's inverse
// bind matrix undoes its (0,1,0). Vertex 0 (0,0,0) follows A; vertex 1
// (1,0,0) A and B with weights 1 and 1 (normalised to a half each); vertex
// 2 (0,2,0) B. B turns about z from 0 at 0 s to 90 degrees at 1 s. With B
// turned by a: B's matrix is T(0,1,0) Rz(a) T(0,-1,0), so
//   vertex 2: (0,2,0) -> (0,1,0) -> (-sin a, cos a, 0) -> (-sin a, 1 + cos a, 0)
//   vertex 1: A (1,0,0); B (1,-1,0) -> (cos a + sin a, sin a - cos a, 0) -> (.., 1 + sin a - cos a, 0);
//             half each: (0.5 (1 + cos a + sin a), 0.5 (1 + sin a - cos a), 0)
// in the file's y-up space, shown z-up: (x, y, z) -> (x, -z, y).
std::string skinned_file(const std::string& joints = "0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0",
                         const std::string& weights = "1, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0", int binds = 2,
                         const std::string& skin_joints = "[1, 2]", bool with_weights = true) {
    Bin bin;
    auto numbers = [](const std::string& list) {
        std::vector<float> v;
        for (size_t at = 0; at < list.size();) {
            size_t used = 0;
            v.push_back(std::stof(list.substr(at), &used));
            at += used;
            while (at < list.size() && (list[at] == ',' || list[at] == ' ')) ++at;
        }
        return v;
    };
    std::vector<int> j;
    for (const float x : numbers(joints)) j.push_back(int(x));
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 2, 0}), jv = bin.u8(j), wv = bin.f32(numbers(weights));
    std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
    ibm.resize(size_t(16 * binds), 0.0f);
    const int b = bin.f32(ibm), times = bin.f32({0, 1}), turn = bin.f32({0, 0, 0, 1, 0, 0, float(kHalfSqrt2), float(kHalfSqrt2)});
    const std::string attributes = with_weights ? R"({"POSITION": 0, "JOINTS_0": 1, "WEIGHTS_0": 2})"
                                                : R"({"POSITION": 0, "JOINTS_0": 1})";
    return gltf_json(R"("scenes": [{"nodes": [0, 1]}],
"nodes": [{"mesh": 0, "skin": 0, "translation": [5, 0, 0]}, {"children": [2]}, {"translation": [0, 1, 0]}],
"skins": [{"joints": )" + skin_joints + R"(, "inverseBindMatrices": 3}],
"meshes": [{"primitives": [{"attributes": )" + attributes + R"(}]}],
"accessors": [)" + joined({accessor(p, kFloat, 3, "VEC3"), accessor(jv, kUnsignedByte, 3, "VEC4"),
                           accessor(wv, kFloat, 3, "VEC4"), accessor(b, kFloat, size_t(binds), "MAT4"),
                           accessor(times, kFloat, 2, "SCALAR"), accessor(turn, kFloat, 2, "VEC4")}) + "], " +
                         animation(channel(0, 2, "rotation"), sampler(4, 5, "LINEAR")),
                     bin);
}

TEST(GltfSkin, ATriangleByHandAtBetweenAndBeyondKeys) {
    Scene s;
    const std::vector<NodeAnimation> animations = add_gltf(s, load(skinned_file()), "m", Transform{});
    ASSERT_EQ(s.deformations.size(), 1u);
    // The bind pose (a = 0): where the file puts the vertices, not moved by node 0's (5,0,0).
    expect_points(world_of(s, 0), {{0, 0, 0}, {1, 0, 0}, {0, 0, 2}}, "bind pose");
    pose_at(s, animations, 0.5);  // a = 45 degrees (slerp halfway)
    const double h = kHalfSqrt2;
    // The file's key holds sin 45 degrees in float: 5e-9 off.
    expect_points(world_of(s, 0), {{0, 0, 0}, {0.5 * (1 + 2 * h), 0, 0.5}, {-h, 0, 1 + h}}, "a = 45", 1e-8);
    for (const double t : {1.0, 3.0}) {  // a = 90 degrees, and held after the last key
        pose_at(s, animations, t);
        expect_points(world_of(s, 0), {{0, 0, 0}, {1, 0, 1}, {-1, 0, 1}}, "t = " + std::to_string(t));
    }
}

TEST(GltfSkin, BadSkinsAreOneLine) {
    auto refused = [](const std::string& json, const std::string& phrase) {
        expect_input_error([&] { load_gltf_from_memory(json, "bad.gltf", "/nonexistent-folder"); }, "bad.gltf", phrase);
    };
    refused(skinned_file("5, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0"),
            "mesh 0 primitive 0 on node 0: vertex 0 names joint 5 of a skin of 2");
    refused(skinned_file("0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0", "1, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0", 1),
            "mesh 0 primitive 0 on node 0: 1 inverse bind matrices for 2 joints");
    refused(skinned_file("0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0", "0, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0"),
            "mesh 0 primitive 0 on node 0: vertex 0 has no joint weight");
    refused(skinned_file("0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0", "nan, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0"),
            "WEIGHTS_0 (accessor 2): a value is not finite (NaN or infinite)");
    refused(skinned_file("0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0", "1, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0", 2, "[1, 9]"),
            "mesh 0 primitive 0 on node 0: joint node 9 does not exist");
    refused(skinned_file("0, 0, 0, 0,  0, 1, 0, 0,  1, 0, 0, 0", "1, 0, 0, 0,  1, 1, 0, 0,  1, 0, 0, 0", 2, "[1, 2]", false),
            "mesh 0 primitive 0 on node 0: JOINTS_0 and WEIGHTS_0 come together");
}

TEST(GltfMorph, BadTargetsAreOneLine) {
    std::string file = morphed_file();
    // Node 1's own weights: one number for two targets.
    file.replace(file.find(R"("weights": [0, 1])"), 17, R"("weights": [1])");
    expect_input_error([&] { load_gltf_from_memory(file, "bad.gltf", "/nonexistent-folder"); }, "bad.gltf",
                       "node 1: 1 morph weights for 2 targets");
}

// Every node deforms its own copy of a morphed mesh: 1,500,000 vertices
// (zeros: sparse accessors without a buffer view) on three nodes is
// 4,500,000 vertices of copies, past the limit of 2^22 = 4,194,304. The
// third node is refused before its copy is made; its target is read once.
TEST(GltfMorph, CopiesPastTheLimitAreRefused) {
    Bin bin;
    const int where = bin.u8({0}), value = bin.f32({0, 0, 1});
    const std::string zeros = R"({"componentType": 5126, "count": 1500000, "type": "VEC3")" +
                              sparse(1, where, kUnsignedByte, value) + "}";
    const std::string file = gltf_json(R"("scenes": [{"nodes": [0, 1, 2]}], "nodes": [{"mesh": 0}, {"mesh": 0}, {"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}]}]}],
"accessors": [)" + zeros + ", " + zeros + "]",
                                       bin);
    expect_input_error([&] { load_gltf_from_memory(file, "big.gltf", "/nonexistent-folder"); }, "big.gltf",
                       "mesh 0 primitive 0 on node 2: morphed and skinned copies of more than 4194304 vertices in all");
}

}  // namespace
}  // namespace fh
