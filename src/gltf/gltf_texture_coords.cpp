#include "gltf/gltf_texture_coords.h"

#include <cmath>

#include "text/input_error.h"

namespace fh {

dvec2 TextureCoords::moved(dvec2 uv) const {
    const double c = std::cos(rotation), s = std::sin(rotation);
    const double u = scale.x * uv.x, v = scale.y * uv.y;
    return {c * u + s * v + offset.x, -s * u + c * v + offset.y};
}

TextureCoords texture_coords_of(int tex_coord, const tinygltf::ExtensionMap& extensions, const std::string& file,
                                const std::string& what) {
    auto fail = [&](const std::string& why) { throw InputError(file, what + ": KHR_texture_transform's " + why); };
    TextureCoords out;
    out.set = tex_coord;
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end()) return out;
    const tinygltf::Value& x = it->second;
    auto pair = [&](const char* key, dvec2& into) {
        if (!x.Has(key)) return;
        const tinygltf::Value& v = x.Get(key);
        if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
            fail(std::string(key) + " needs 2 numbers");
        into = {v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble()};
    };
    pair("offset", out.offset);
    pair("scale", out.scale);
    if (x.Has("rotation")) {
        if (!x.Get("rotation").IsNumber()) fail("rotation is not a number");
        out.rotation = x.Get("rotation").GetNumberAsDouble();
    }
    if (x.Has("texCoord")) {
        if (!x.Get("texCoord").IsInt() || x.Get("texCoord").GetNumberAsInt() < 0) fail("texCoord is not a set index");
        out.set = x.Get("texCoord").GetNumberAsInt();
    }
    if (!std::isfinite(out.offset.x + out.offset.y + out.scale.x + out.scale.y + out.rotation))
        fail("numbers are not finite");
    return out;
}

std::optional<TextureCoords> carried_coords(const tinygltf::Material& mat, const std::string& file,
                                            const std::string& what) {
    const tinygltf::TextureInfo& base = mat.pbrMetallicRoughness.baseColorTexture;
    if (base.index >= 0) return texture_coords_of(base.texCoord, base.extensions, file, what);
    if (mat.emissiveTexture.index >= 0)
        return texture_coords_of(mat.emissiveTexture.texCoord, mat.emissiveTexture.extensions, file, what);
    if (mat.occlusionTexture.index >= 0)
        return texture_coords_of(mat.occlusionTexture.texCoord, mat.occlusionTexture.extensions, file, what);
    if (mat.normalTexture.index >= 0)
        return texture_coords_of(mat.normalTexture.texCoord, mat.normalTexture.extensions, file, what);
    const tinygltf::TextureInfo& mr = mat.pbrMetallicRoughness.metallicRoughnessTexture;
    if (mr.index >= 0) return texture_coords_of(mr.texCoord, mr.extensions, file, what);
    return std::nullopt;
}

}  // namespace fh
