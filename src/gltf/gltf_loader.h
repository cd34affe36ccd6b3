// glTF 2.0 files (`.gltf`, `.glb`) as firsthit scenes (docs/gltf.md): the
// node hierarchy as scene nodes (scene/node.h); each mesh primitive a mesh
// loaded once and placed by every node that uses it (instances, the second
// level: no copies); cameras, KHR_lights_punctual lights and
// pbrMetallicRoughness materials mapped onto the report's camera, lights and
// materials by documented formulas; animations as node channels
// (anim/node_channel.h), evaluated as the specification's Appendix C says.
// Every problem is one InputError naming the file (gltf/gltf_model.h lists
// what is checked before tinygltf reads it).
#pragma once

#include <string>
#include <vector>

#include "anim/node_channel.h"
#include "scene/scene.h"

namespace fh {

struct GltfFile {
    // The file's materials, meshes, nodes (parents first; its top nodes in
    // no group), the instances of its meshes, its cameras and lights -- all
    // in the file's own y-up space, not yet placed.
    Scene scene;
    std::vector<NodeAnimation> animations;  // their channels' nodes index scene.nodes
    std::vector<std::string> warnings;      // one line each, "FILE: warning: ..."
};

// exposure: multiplies every light's intensity (1: the documented units),
// 0 to kMaxExposure (--exposure and a surface's `exposure:` alike).
inline constexpr double kMaxExposure = 1e6;
GltfFile load_gltf(const std::string& path, double exposure = 1);
GltfFile load_gltf_from_memory(const std::string& bytes, const std::string& file, const std::string& folder,
                               double exposure = 1);

// The file is named so (the loaders take it by content).
bool is_gltf_file(const std::string& path);

// `file` placed in `scene`: a group `name` holding the file (turned from
// glTF's y-up to firsthit's z-up, +90 degrees about x) placed by
// `transform` inside group `parent` (-1: the world); the file's materials,
// meshes, nodes, instances, cameras and lights added to the scene's, and
// its animations' channels renumbered to the scene's nodes. Returns them.
std::vector<NodeAnimation> add_gltf(Scene& scene, GltfFile file, const std::string& name, const Transform& transform,
                                    int parent = -1);

}  // namespace fh
