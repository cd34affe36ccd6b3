// A glTF file's node hierarchy: the nodes of the scene it shows, parents
// before children (a cycle or a node with two parents refused), each
// node's own transform (matrix or TRS), and EXT_mesh_gpu_instancing's rows.
// Problems are InputError naming the file.
#pragma once

#include <string>
#include <vector>

#include "gltf/accessors.h"
#include "scene/node.h"

namespace fh {

struct GltfNodeOrder {
    std::vector<int> order;      // the shown scene's nodes (file indices), every parent before its children
    std::vector<int> new_index;  // file index -> position in order (-1: not shown)
    std::vector<int> parent;     // file index -> its parent's file index (-1: none)
};

// The scene's nodes in an order with every parent before its children,
// each node reached once: a node with two parents, or a cycle, is refused.
GltfNodeOrder order_gltf_nodes(const tinygltf::Model& model, const std::string& file);

// Node `index`'s name (its own, or "node N") and its transform, checked
// (the right count of numbers, finite); its parent is left to the caller.
SceneNode gltf_scene_node(const tinygltf::Node& node, int index, const std::string& file);

// Where EXT_mesh_gpu_instancing puts copies within the node: one matrix
// a row (T * R * S); none without it (the node itself). name: the node's.
std::vector<glm::dmat4> gltf_instancing_rows(const tinygltf::Node& node, const AccessorReader& read,
                                             const std::string& name);

}  // namespace fh
