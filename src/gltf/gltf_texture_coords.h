// The texture coordinates a glTF texture reads (docs/gltf.md, "Textures"):
// the TEXCOORD set its textureInfo names, moved by its KHR_texture_transform
// (uv' = translate(offset) rotate(rotation) scale(scale) uv), whose texCoord,
// when it has one, overrides the set. A mesh carries one such set of
// coordinates (Mesh::uvs); a material's other textures are drawn when they
// read the same.
#pragma once

#include <optional>
#include <string>

#include "gltf/gltf_model.h"

namespace fh {

struct TextureCoords {
    int set = 0;
    dvec2 offset{0}, scale{1};
    double rotation = 0;

    bool operator==(const TextureCoords&) const = default;
    dvec2 moved(dvec2 uv) const;  // the transform applied to one coordinate pair
};

// The coordinates of a textureInfo (its texCoord and extensions); a bad
// transform is an InputError naming `file` and, in its message, `what`.
TextureCoords texture_coords_of(int tex_coord, const tinygltf::ExtensionMap& extensions, const std::string& file,
                                const std::string& what);

// The coordinates a material's primitives carry: those of its base colour
// texture, else of its emissive texture, else of its occlusion texture,
// else of its normal texture, else of its metallic-roughness texture;
// nothing when it has none of them.
std::optional<TextureCoords> carried_coords(const tinygltf::Material& mat, const std::string& file,
                                            const std::string& what);

}  // namespace fh
