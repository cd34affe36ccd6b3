// glTF materials onto the report's (docs/gltf.md, "Materials" and
// "Textures"): pbrMetallicRoughness's factors as the report's colours and
// strengths by a documented formula, the base colour texture with its
// sampler, alpha cutouts. Problems are InputError naming the file.
#pragma once

#include <string>

#include "gltf/gltf_model.h"
#include "scene/scene.h"

namespace fh {

struct GltfMaterialsAdded {
    int default_material = 0;  // glTF's default material, for primitives without one
    int unused_textures = 0;   // textures not drawn (on other coordinates than their mesh carries)
};

// Every material of the file, in its order, then glTF's default material,
// added to the scene's materials (and their textures to its textures).
GltfMaterialsAdded add_gltf_materials(const tinygltf::Model& model, const std::string& file, Scene& scene);

}  // namespace fh
