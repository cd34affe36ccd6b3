// Meshes whose vertices move (glTF's morph targets and skins; docs/gltf.md):
// each keeps its rest pose, and deform_meshes writes the pose its node
// stands in -- the node's morph weights, its skin's joints -- into the scene
// mesh its instances place, as a new copy (a frame's scene shares nothing
// that another frame's changes).
//
//   morph:  p = rest + sum_i w_i target_i      (normals alike, then unit)
//   skin:   p' = sum_k w_k M_k p,  M_k = N^-1 J_k B_k
// with J_k a joint's world matrix, B_k its inverse bind matrix and N the
// world matrix of the node the mesh hangs on: glTF places a skinned mesh by
// its joints alone, and its instance, placed by N, brings it back there.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/mesh.h"

namespace fh {

struct Scene;

// Displacements of every vertex, added times the target's weight.
struct MorphTarget {
    std::vector<dvec3> positions;  // one per vertex
    std::vector<dvec3> normals;    // one per vertex, or empty
    std::vector<dvec3> tangents;   // one per vertex (added to a TANGENT's xyz), or empty
};

// Linear blend skinning's per-vertex part: each vertex moved by up to
// `influences` of its skin's joints.
struct SkinWeights {
    int influences = 0;                // joints per vertex
    std::vector<std::uint32_t> joint;  // vertices x influences, into the skin's joints
    std::vector<double> weight;        // vertices x influences, each vertex's summing to 1
};

struct Skin {
    std::vector<int> joints;                // scene nodes
    std::vector<glm::dmat4> inverse_binds;  // one per joint
    std::shared_ptr<const SkinWeights> weights;  // null: no skin
};

// What the nodes using one primitive share -- its rest pose, targets and
// weights -- is shared, not copied: each node only adds its deformed copy.
struct Deformation {
    int mesh = 0;  // into Scene::meshes: receives the deformed copy
    int node = 0;  // the node it hangs on: its `weights` morph it; its space holds the skinned result
    std::shared_ptr<const Mesh> rest;
    std::shared_ptr<const std::vector<MorphTarget>> targets;  // null: none
    Skin skin;
};

// The rest mesh morphed by `weights` (one per target; missing ones 0) and
// skinned by `joint_matrices` (M_k above, one per joint; unused without a
// skin).
Mesh deformed(const Deformation& d, const std::vector<double>& weights, const std::vector<glm::dmat4>& joint_matrices);

// Every deformation of the scene at its nodes' current state.
void deform_meshes(Scene& scene);

}  // namespace fh
