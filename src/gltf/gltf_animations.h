// A glTF animation read into node channels (anim/node_channel.h): each
// channel's target node and path (translation, rotation, scale or morph
// weights) and its sampler's keys, interpolation and values, checked as
// the specification requires (docs/gltf.md, "Animations"); evaluating them
// is anim/sampler.h's. Only the .cpp files of src/gltf include this header.
#pragma once

#include <vector>

#include "anim/node_channel.h"
#include "gltf/accessors.h"
#include "scene/node.h"

namespace fh {

// Animation `index` of `model`. scene_node: each glTF node's index among
// the scene's nodes (-1 for a node outside the scene shown, whose channels
// are left out); nodes: the scene's nodes.
NodeAnimation read_gltf_animation(const tinygltf::Model& model, int index, const AccessorReader& read,
                                  const std::vector<int>& scene_node, const std::vector<SceneNode>& nodes);

}  // namespace fh
