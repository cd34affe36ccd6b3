#include "gltf/gltf_primitives.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_texture_coords.h"
#include "meshes/mesh_loader.h"

namespace fh {

namespace {

// A primitive's reads, every problem through the accessor reader's
// InputError.
class PrimitiveReader {
public:
    PrimitiveReader(const tinygltf::Model& model, const AccessorReader& read) : m_(model), read_(read) {}

    void check_primitive(const tinygltf::Primitive& prim, const std::string& what) const {
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) fail(what + ": no POSITION attribute");
        const size_t vertices = read_.count(position->second, what + " POSITION");
        for (const auto& [name, accessor] : prim.attributes)
            if (read_.count(accessor, what + " " + name) != vertices)
                fail(what + ": " + name + " has " + std::to_string(read_.count(accessor, what)) + " elements, POSITION " +
                     std::to_string(vertices));
        const size_t n = prim.indices >= 0 ? read_.count(prim.indices, what + " indices") : vertices;
        const bool ok = prim.mode == TINYGLTF_MODE_TRIANGLES ? n % 3 == 0
                        : prim.mode == TINYGLTF_MODE_LINE ? n % 2 == 0
                        : prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP || prim.mode == TINYGLTF_MODE_TRIANGLE_FAN ? n >= 3
                        : prim.mode == TINYGLTF_MODE_LINE_STRIP || prim.mode == TINYGLTF_MODE_LINE_LOOP ? n >= 2
                                                                                                       : n >= 1;
        if (!ok) fail(what + ": " + std::to_string(n) + (prim.indices >= 0 ? " indices" : " vertices") +
                      " do not make whole " + (prim.mode <= TINYGLTF_MODE_LINE_STRIP ? "lines" : "triangles") +
                      " in mode " + std::to_string(prim.mode));
        if (prim.material < 0 || size_t(prim.material) >= m_.materials.size()) return;
        const tinygltf::Material& mat = m_.materials[size_t(prim.material)];
        const tinygltf::PbrMetallicRoughness& pbr = mat.pbrMetallicRoughness;
        for (const int set : {set_read_by(pbr.baseColorTexture), set_read_by(pbr.metallicRoughnessTexture),
                              set_read_by(mat.normalTexture), set_read_by(mat.occlusionTexture),
                              set_read_by(mat.emissiveTexture)})
            if (set >= 0 && !prim.attributes.count("TEXCOORD_" + std::to_string(set)))
                fail(what + ": its material reads TEXCOORD_" + std::to_string(set) + ", which it does not have");
    }

    // The TEXCOORD set a texture reads (-1: no texture): its textureInfo's
    // own, or its KHR_texture_transform's texCoord, which overrides it.
    template <typename TextureInfo>
    static int set_read_by(const TextureInfo& info) {
        if (info.index < 0) return -1;
        if (const tinygltf::Value* t = extension_value(info.extensions, "KHR_texture_transform", "texCoord"))
            if (t->IsInt()) return t->GetNumberAsInt();
        return info.texCoord;
    }

    // The texture coordinates the primitive's material reads
    // (gltf/gltf_texture_coords.h: its base colour texture's, else its
    // emissive, occlusion, normal or metallic-roughness texture's), moved
    // by that texture's transform. Empty when its material has none of
    // those textures.
    std::vector<dvec2> read_uvs(const tinygltf::Primitive& prim, const std::string& what) const {
        if (prim.material < 0 || size_t(prim.material) >= m_.materials.size()) return {};
        const std::optional<TextureCoords> coords =
            carried_coords(m_.materials[size_t(prim.material)], read_.file(), what);
        if (!coords) return {};
        const int set = coords->set;
        const auto attribute = prim.attributes.find("TEXCOORD_" + std::to_string(set));
        if (attribute == prim.attributes.end())
            fail(what + ": its material reads TEXCOORD_" + std::to_string(set) + ", which it does not have");
        const std::vector<double> t = read_.numbers(attribute->second, 2, what + " TEXCOORD_" + std::to_string(set));
        std::vector<dvec2> uvs(t.size() / 2);
        for (size_t i = 0; i < uvs.size(); ++i) {
            uvs[i] = coords->moved({t[2 * i], t[2 * i + 1]});
            if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y))
                fail(what + ": KHR_texture_transform takes TEXCOORD_" + std::to_string(set) + " " +
                     std::to_string(i) + " past a double's range");
        }
        return uvs;
    }

    // COLOR_0, linear: a VEC3 or VEC4 of floats or normalized unsigned
    // bytes or shorts, each channel clamped to [0, 1], into mesh.colors; a
    // VEC4's alphas into mesh.alphas unless every one is 1. Nothing when the
    // primitive has none.
    void read_colors(const tinygltf::Primitive& prim, const std::string& what, Mesh& mesh) const {
        const auto attribute = prim.attributes.find("COLOR_0");
        if (attribute == prim.attributes.end()) return;
        const int index = attribute->second;
        if (index < 0 || size_t(index) >= m_.accessors.size()) fail(what + ": COLOR_0's accessor does not exist");
        const tinygltf::Accessor& a = m_.accessors[size_t(index)];
        if (a.type != TINYGLTF_TYPE_VEC3 && a.type != TINYGLTF_TYPE_VEC4) fail(what + ": COLOR_0 is not a VEC3 or VEC4");
        const bool normalized_int = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                     a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_int)
            fail(what + ": COLOR_0 is not floats or normalized unsigned bytes or shorts");
        const int components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
        const std::vector<double> c = read_.numbers(index, components, what + " COLOR_0");
        const size_t n = c.size() / size_t(components);
        mesh.colors.resize(n);
        if (components == 4) mesh.alphas.resize(n);
        bool translucent = false;
        for (size_t i = 0; i < n; ++i) {
            const double* x = &c[size_t(components) * i];
            mesh.colors[i] = glm::clamp(dvec3(x[0], x[1], x[2]), 0.0, 1.0);
            if (components < 4) continue;
            mesh.alphas[i] = std::clamp(x[3], 0.0, 1.0);
            translucent |= mesh.alphas[i] < 1;
        }
        if (!translucent) mesh.alphas.clear();
    }

    // The primitive's TANGENT, where its material has a normal texture to
    // read it by and its mesh has NORMALs (without them the specification
    // has tangents ignored): xyz as they are, w as its sign. Without
    // TANGENT, they are made from the normals and coordinates at each pose
    // (Mesh::make_tangents).
    void read_tangents(const tinygltf::Primitive& prim, const std::string& what, Mesh& mesh) const {
        if (mesh.normals.empty() || mesh.uvs.empty() || prim.material < 0 ||
            size_t(prim.material) >= m_.materials.size() || m_.materials[size_t(prim.material)].normalTexture.index < 0)
            return;
        const auto tangent = prim.attributes.find("TANGENT");
        if (tangent == prim.attributes.end()) {
            mesh.make_tangents = true;
            return;
        }
        const std::vector<double> t = read_.numbers(tangent->second, 4, what + " TANGENT");
        if (t.size() != 4 * mesh.positions.size())
            fail(what + ": TANGENT has " + std::to_string(t.size() / 4) + " elements, POSITION " +
                 std::to_string(mesh.positions.size()));
        mesh.tangents.resize(mesh.positions.size());
        for (size_t i = 0; i < mesh.tangents.size(); ++i)
            mesh.tangents[i] = {t[4 * i], t[4 * i + 1], t[4 * i + 2], t[4 * i + 3] < 0 ? -1.0 : 1.0};
    }

    Mesh read_primitive(const tinygltf::Primitive& prim, const std::string& what) const {
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) fail(what + ": no POSITION attribute");
        Mesh mesh;
        const std::vector<double> p = read_.numbers(position->second, 3, what + " POSITION");
        const size_t vertices = p.size() / 3;
        for (size_t i = 0; i < vertices; ++i) mesh.positions.push_back({p[3 * i], p[3 * i + 1], p[3 * i + 2]});
        if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end()) {
            const std::vector<double> n = read_.numbers(normal->second, 3, what + " NORMAL");
            if (n.size() != p.size()) fail(what + ": NORMAL has " + std::to_string(n.size() / 3) + " elements, POSITION " + std::to_string(vertices));
            for (size_t i = 0; i < vertices; ++i) mesh.normals.push_back({n[3 * i], n[3 * i + 1], n[3 * i + 2]});
            mesh.smooth = true;
        }
        std::vector<std::uint32_t> index;
        if (prim.indices >= 0) {
            index = read_.indices(prim.indices, std::uint32_t(std::min<size_t>(vertices, 0xffffffffu)), what + " indices");
        } else {
            if (vertices > 0xffffffffu) fail(what + ": too many vertices");
            index.resize(vertices);
            for (size_t i = 0; i < vertices; ++i) index[i] = std::uint32_t(i);
        }
        // Triangles, strips and fans as the specification numbers them.
        auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { mesh.triangles.push_back({a, b, c}); };
        const size_t n = index.size();
        if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < n; i += 3) add(index[i], index[i + 1], index[i + 2]);
        } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < n; ++i)
                add(index[i], index[i + 1 + i % 2], index[i + 2 - i % 2]);
        } else {
            for (size_t i = 1; i + 1 < n; ++i) add(index[i], index[i + 1], index[0]);
        }
        if (mesh.triangles.size() > kMaxMeshTriangles)
            fail(what + ": " + std::to_string(mesh.triangles.size()) + " triangles (the limit is " + std::to_string(kMaxMeshTriangles) + ")");
        return mesh;
    }

private:
    [[noreturn]] void fail(const std::string& what) const { read_.fail(what); }

    const tinygltf::Model& m_;
    const AccessorReader& read_;
};

}  // namespace

void check_gltf_primitive(const tinygltf::Model& model, const AccessorReader& read, const tinygltf::Primitive& prim,
                          const std::string& what) {
    PrimitiveReader(model, read).check_primitive(prim, what);
}

Mesh read_gltf_primitive(const tinygltf::Model& model, const AccessorReader& read, const tinygltf::Primitive& prim,
                         const std::string& what) {
    const PrimitiveReader reader(model, read);
    Mesh mesh = reader.read_primitive(prim, what);
    mesh.uvs = reader.read_uvs(prim, what);
    reader.read_tangents(prim, what, mesh);
    reader.read_colors(prim, what, mesh);
    return mesh;
}

}  // namespace fh
