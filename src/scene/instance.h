// Many objects: a mesh loaded once and placed many times (instances), and
// groups that carry what they hold under one transform. An instance's
// triangles stay in the mesh's own space; the tracer brings rays to them
// (render/instance_set.h), so a thousand copies cost a thousand matrices,
// not a thousand copies of the triangles.
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <string>

#include <glm/mat4x4.hpp>

#include "scene/mesh.h"

namespace fh {

// A scene may hold this many instances: each costs ~1.1 KB at the peak of
// loading and preparing, in double (its placement as read and as placed,
// its maps in the tracer's type, its box, its share of the top-level BVH
// and of the builder's work; 400,000 took 444 MB), so 4 million take ~4.5 GB.
inline constexpr std::size_t kMaxInstances = 4'000'000;

// A `meshes:` entry: one file, read once, in its own space.
struct SceneMesh {
    std::string name;
    std::shared_ptr<const Mesh> mesh;  // material unused: each instance gives its own
};

// One placement of a SceneMesh.
struct Instance {
    int mesh = 0;      // into Scene::meshes
    int material = 0;  // into Scene::materials
    glm::dmat4 to_world{1.0};  // object space -> world; invertible (the loaders check)
    // A glTF mesh: the scene node that places it (scene/node.h), and where
    // in that node's space: EXT_mesh_gpu_instancing's row in
    // Scene::instance_rows, or -1 at the node itself (kept apart: most
    // instances have none).
    int node = -1;
    int row = -1;
};

// A `type: group`: what it holds moves with its transform.
struct Group {
    std::string name;
    Transform transform;  // in its parent's space
    int parent = -1;      // the group it is in; -1: the world
};

// The world matrix of every group, parents before children (a group's
// parent always comes first): world[g] = world[parent] * transform.
std::vector<glm::dmat4> group_matrices(const std::vector<Group>& groups);

// Whether group `holder` holds what sits in group `group` (-1: the world),
// at any depth.
bool group_holds(const std::vector<Group>& groups, std::size_t holder, int group);

// Every element of `m` is finite.
bool is_finite(const glm::dmat4& m);

// How far a transform may scale along any axis: the float tracer squares
// directions carried through an instance's maps (and their inverses).
inline constexpr double kMinTransformScale = 1e-12, kMaxTransformScale = 1e12;
inline bool within_scale_limits(double scale) {
    return std::abs(scale) >= kMinTransformScale && std::abs(scale) <= kMaxTransformScale;
}

// Why `m` cannot place anything -- not finite, scaling an axis outside
// kMin/kMaxTransformScale, or singular (its axes in a plane) -- or empty
// when it can.
std::string unusable_transform(const glm::dmat4& m);

// `m`, or where a movie's frame puts an instance whose composed transform is
// unusable there: the zero map, which shows nothing (as glTF's scale 0).
glm::dmat4 usable_or_nothing(const glm::dmat4& m);

}  // namespace fh
