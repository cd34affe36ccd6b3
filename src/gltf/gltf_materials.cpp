#include "gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

#include "gltf/gltf_texture_coords.h"
#include "text/input_error.h"

namespace fh {

namespace {

// pbrMetallicRoughness onto the report's material (docs/gltf.md, "Materials"):
// c = 255 baseColor; a metal's highlight is tinted and its diffuse part only
// what roughness scatters (a rough metal -- glTF's default material -- looks
// matte, a polished one mirrors); roughness r widens the highlight
// (Blinn-Phong exponent 2 / a^2 - 2, a = r^2) and dims it. The ambient
// strength is the report's materials' 0.1, so that a model placed in a scene
// file is lit by that file's ambient light as the file's own surfaces are
// (at 1 the bunny scene's ambient light alone made the engine white).
Material<double> material_of(const tinygltf::Material& m) {
    const auto& pbr = m.pbrMetallicRoughness;
    const dvec3 base = pbr.baseColorFactor.size() >= 3
                           ? dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2])
                           : dvec3(1);
    const double metal = std::clamp(pbr.metallicFactor, 0.0, 1.0), rough = std::clamp(pbr.roughnessFactor, 0.0, 1.0);
    Material<double> out;
    out.ambient_color = out.diffuse_color = 255.0 * glm::clamp(base, 0.0, 1.0);
    out.specular_color = metal * out.diffuse_color + (1 - metal) * dvec3(255);
    out.ambient = 0.1;
    out.diffuse = (1 - metal) + metal * rough;
    out.specular = (0.04 + 0.96 * metal) * (1 - rough);
    const double a = std::max(rough * rough, 0.01);
    out.phong_exponent = std::min(2 / (a * a) - 2, 10000.0);
    out.glazed = metal > 0.5 && rough < 0.5;
    out.reflectivity = out.glazed ? metal * (1 - rough) * (1 - rough) : 0;
    out.metallic = metal;  // for a metallic-roughness texture, which scales them per hit
    out.roughness = rough;
    double strength = 1;
    if (const tinygltf::Value* s = extension_value(m.extensions, "KHR_materials_emissive_strength", "emissiveStrength"))
        if (s->IsNumber()) strength = s->GetNumberAsDouble();
    out.emissive = 255.0 * strength * glm::max(vec3_or(m.emissiveFactor, dvec3(0)), dvec3(0));
    return out;
}

// The materials' textures and alpha modes, each glTF texture and image
// made once however many materials show it.
class MaterialReader {
public:
    MaterialReader(const tinygltf::Model& model, const std::string& file) : m_(model), file_(file) {}

    // The textures and alpha mode of material `mat` (the last of
    // s.materials) onto it (docs/gltf.md, "Textures"): its base colour
    // texture, and its emissive, occlusion, normal and metallic-roughness
    // textures where they read the coordinates its meshes carry
    // (gltf/gltf_texture_coords.h).
    void add_surface_of(const tinygltf::Material& mat, const std::string& name, Scene& s) {
        Material<double>& out = s.materials.back();
        const auto& pbr = mat.pbrMetallicRoughness;
        // (Its alpha hides texels only where the surface is MASKed or BLENDed.)
        const bool see_through = mat.alphaMode == "MASK" || mat.alphaMode == "BLEND";
        if (pbr.baseColorTexture.index >= 0)
            out.texture = texture_of(pbr.baseColorTexture.index, name, s, true, see_through);
        // The coordinates are compared only where the material has an
        // emissive, occlusion, normal or metallic-roughness texture; then a
        // bad transform of any of its textures is reported with the
        // material's name, and otherwise, as before these were drawn, with
        // the primitive that reads it. Each such texture's image and sampler
        // must be good once it is drawn, as the base colour texture's must.
        if (mat.occlusionTexture.index >= 0 && !(mat.occlusionTexture.strength >= 0 && mat.occlusionTexture.strength <= 1))
            fail(name + ": occlusionTexture's strength must be in [0, 1]");
        std::optional<TextureCoords> carried;
        if (mat.emissiveTexture.index >= 0 || mat.occlusionTexture.index >= 0 || mat.normalTexture.index >= 0 ||
            pbr.metallicRoughnessTexture.index >= 0)
            carried = carried_coords(mat, file_, name);
        auto drawn = [&](const auto& info) {
            const bool same = info.index >= 0 && texture_coords_of(info.texCoord, info.extensions, file_, name) == *carried;
            unused_textures_ += info.index >= 0 && !same;
            return same;
        };
        if (drawn(mat.emissiveTexture)) out.emissive_texture = texture_of(mat.emissiveTexture.index, name, s, true);
        if (drawn(mat.occlusionTexture)) {
            out.occlusion_texture = texture_of(mat.occlusionTexture.index, name, s, false);
            out.occlusion_strength = mat.occlusionTexture.strength;
        }
        if (drawn(mat.normalTexture)) {
            out.normal_texture = texture_of(mat.normalTexture.index, name, s, false);
            // Past a million the direction no longer changes; its square
            // would overflow a float's range.
            out.normal_scale = std::clamp(mat.normalTexture.scale, -1e6, 1e6);
        }
        if (drawn(pbr.metallicRoughnessTexture))
            out.metal_rough_texture = texture_of(pbr.metallicRoughnessTexture.index, name, s, false);
        const double alpha = pbr.baseColorFactor.size() == 4 ? std::clamp(pbr.baseColorFactor[3], 0.0, 1.0) : 1.0;
        if (mat.alphaMode == "MASK") {
            out.cutout = true;
            out.alpha = alpha;
            if (!std::isfinite(mat.alphaCutoff) || mat.alphaCutoff < 0) fail(name + ": alphaCutoff must be >= 0");
            out.alpha_cutoff = mat.alphaCutoff;
        } else if (mat.alphaMode == "BLEND") {
            out.blend = true;
            out.alpha = alpha;
        } else if (mat.alphaMode != "OPAQUE") {
            fail(name + ": alphaMode '" + mat.alphaMode + "' is not OPAQUE, MASK or BLEND");
        }
    }

    // The scene texture of glTF texture `index`, read as colour (srgb) or
    // as data, its alpha hiding texels or not (see_through: its mipmaps
    // weigh colour by alpha): its image (decoded by gltf_model.cpp) and
    // mipmaps shared with every texture that shows it, and its sampler's
    // wrap modes and filters.
    int texture_of(int index, const std::string& name, Scene& s, bool srgb, bool see_through = false) {
        if (index < 0 || size_t(index) >= m_.textures.size()) fail(name + ": texture " + std::to_string(index) + " does not exist");
        const std::tuple<int, bool, bool> key{index, srgb, see_through};
        if (const auto it = textures_.find(key); it != textures_.end()) return it->second;
        const tinygltf::Texture& t = m_.textures[size_t(index)];
        const std::string what = "texture " + std::to_string(index);
        if (t.source < 0 || size_t(t.source) >= m_.images.size()) fail(what + ": it has no image firsthit can read");
        auto& image = images_[t.source];
        if (!image) {
            const tinygltf::Image& in = m_.images[size_t(t.source)];
            if (in.width <= 0 || in.height <= 0 || in.image.size() != 4 * size_t(in.width) * size_t(in.height))
                fail("image " + std::to_string(t.source) + ": no pixels were read");
            image = std::make_shared<const TextureImage>(TextureImage{in.width, in.height, in.image});
        }
        Texture out;
        out.image = image;
        out.srgb = srgb;
        if (t.sampler >= 0) {
            if (size_t(t.sampler) >= m_.samplers.size()) fail(what + ": sampler " + std::to_string(t.sampler) + " does not exist");
            const tinygltf::Sampler& sm = m_.samplers[size_t(t.sampler)];
            auto wrap = [&](int mode) {
                if (mode == TINYGLTF_TEXTURE_WRAP_REPEAT) return Wrap::repeat;
                if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Wrap::mirrored_repeat;
                if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Wrap::clamp_to_edge;
                fail(what + ": wrap mode " + std::to_string(mode) + " is not glTF's (10497, 33648 or 33071)");
            };
            out.wrap_s = wrap(sm.wrapS);
            out.wrap_t = wrap(sm.wrapT);
            if (sm.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.filter = Filter::nearest;
            else if (sm.magFilter != -1 && sm.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
                fail(what + ": magFilter " + std::to_string(sm.magFilter) + " is not glTF's (9728 or 9729)");
            minify(sm.minFilter, what, out);
        } else {
            minify(-1, what, out);
        }
        if (out.mips != MipFilter::none) {
            auto& chain = chains_[{t.source, srgb, see_through}];
            if (!chain) chain = mip_chain(*image, srgb, see_through);
            out.smaller = chain;
        }
        s.textures.push_back(std::move(out));
        return textures_[key] = int(s.textures.size()) - 1;
    }

    int unused_textures_ = 0;

private:
    // The minified texture's filters by glTF's minFilter: within a level
    // (its first word) and between mipmap levels (its last); undefined
    // (-1): trilinear, as glTF viewers choose.
    void minify(int min_filter, const std::string& what, Texture& out) const {
        switch (min_filter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST: out.min_filter = Filter::nearest, out.mips = MipFilter::none; return;
        case TINYGLTF_TEXTURE_FILTER_LINEAR: out.min_filter = Filter::bilinear, out.mips = MipFilter::none; return;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            out.min_filter = Filter::nearest, out.mips = MipFilter::nearest;
            return;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
            out.min_filter = Filter::bilinear, out.mips = MipFilter::nearest;
            return;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
            out.min_filter = Filter::nearest, out.mips = MipFilter::linear;
            return;
        case -1:
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
            out.min_filter = Filter::bilinear, out.mips = MipFilter::linear;
            return;
        default: fail(what + ": minFilter " + std::to_string(min_filter) + " is not glTF's (9728, 9729 or 9984-9987)");
        }
    }

    [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, what); }

    const tinygltf::Model& m_;
    const std::string& file_;
    std::map<std::tuple<int, bool, bool>, int> textures_;  // glTF texture, as colour, see-through -> Scene::textures
    std::map<int, std::shared_ptr<const TextureImage>> images_;  // glTF image, decoded
    std::map<std::tuple<int, bool, bool>, std::shared_ptr<const MipChain>> chains_;  // glTF image, as colour, see-through
};

}  // namespace

GltfMaterialsAdded add_gltf_materials(const tinygltf::Model& model, const std::string& file, Scene& s) {
    MaterialReader reader(model, file);
    for (const tinygltf::Material& mat : model.materials) {
        s.material_names.push_back(mat.name.empty() ? "material " + std::to_string(s.materials.size()) : mat.name);
        s.materials.push_back(material_of(mat));
        reader.add_surface_of(mat, s.material_names.back(), s);
    }
    GltfMaterialsAdded out;
    out.default_material = int(s.materials.size());
    s.material_names.push_back("glTF default");
    s.materials.push_back(material_of(tinygltf::Material{}));
    out.unused_textures = reader.unused_textures_;
    return out;
}

}  // namespace fh
