// The types of a glTF file's JSON, checked against the glTF 2.0 schema's
// before tinygltf reads it: tinygltf passes over a field of the wrong type
// (an object where an array belongs, a string for an index), which would
// leave a mesh quietly empty. Each object's known fields, required or not,
// are checked; unknown fields and `extras` pass, and every `extensions`
// must be an object of objects. A mismatch is one InputError naming the
// field by its path: "meshes[0].primitives: expected an array, got an object".
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace fh {

void check_gltf_schema(const nlohmann::json& root, const std::string& file);

}  // namespace fh
