// Loading the glTF files the tests write (gltf_builder.h): as read, with
// the nodes placed (still y-up), or added to a scene z-up.
#pragma once

#include "gltf/gltf_builder.h"
#include "gltf/gltf_loader.h"
#include "scene/node.h"

namespace fh::gltf_test {

inline GltfFile load(const std::string& json, double exposure = 1) {
    return load_gltf_from_memory(json, "t.gltf", "/nonexistent-folder", exposure);
}

// The file with everything on its nodes placed, still in its own y-up space.
inline GltfFile placed(const std::string& json, double exposure = 1) {
    GltfFile f = load(json, exposure);
    place_nodes(f.scene);
    return f;
}

// The file placed z-up by add_gltf, moved by `where`.
inline Scene z_up(const std::string& json, const Transform& where = {}) {
    Scene s;
    add_gltf(s, load(json), "m", where);
    return s;
}

inline dvec3 apply(const glm::dmat4& m, const dvec3& p) { return dvec3(m * glm::dvec4(p, 1.0)); }

}  // namespace fh::gltf_test
