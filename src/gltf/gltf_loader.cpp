#include "gltf/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <tuple>

#include "gltf/accessors.h"
#include "gltf/gltf_animations.h"
#include "gltf/gltf_cameras_lights.h"
#include "gltf/gltf_deform.h"
#include "meshes/mesh_loader.h"
#include "text/input_error.h"

namespace fh {

namespace {

// A value of an extension object, or null.
const tinygltf::Value* extension_value(const tinygltf::ExtensionMap& extensions, const std::string& name,
                                       const std::string& key) {
    const auto it = extensions.find(name);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return nullptr;
    return &it->second.Get(key);
}

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
    double strength = 1;
    if (const tinygltf::Value* s = extension_value(m.extensions, "KHR_materials_emissive_strength", "emissiveStrength"))
        if (s->IsNumber()) strength = s->GetNumberAsDouble();
    out.emissive = 255.0 * strength * glm::max(vec3_or(m.emissiveFactor, dvec3(0)), dvec3(0));
    return out;
}

class Converter {
public:
    Converter(const tinygltf::Model& model, std::string file, double exposure)
        : m_(model), file_(std::move(file)), read_(model, file_), exposure_(exposure) {}

    GltfFile convert() {
        GltfFile out;
        Scene& s = out.scene;
        for (const tinygltf::Material& mat : m_.materials) {
            s.material_names.push_back(mat.name.empty() ? "material " + std::to_string(s.materials.size()) : mat.name);
            s.materials.push_back(material_of(mat));
            add_surface_of(mat, s.material_names.back(), s);
        }
        default_material_ = int(s.materials.size());
        s.material_names.push_back("glTF default");
        s.materials.push_back(material_of(tinygltf::Material{}));
        order_nodes();
        check_geometry_size();
        for (const int n : order_) add_node(n, s);
        // Each node's own numbers are finite; their products must be too
        // (a scale of 1e200 under another is infinite).
        const std::vector<glm::dmat4> world = node_matrices(s);
        for (size_t n = 0; n < world.size(); ++n)
            if (!is_finite(world[n]))
                fail(s.nodes[n].name + ": its transform times its parents' is not finite (past a double's range)");
        for (const Instance& i : s.instances)
            if (i.row >= 0 && !is_finite(world[size_t(i.node)] * s.instance_rows[size_t(i.row)]))
                fail(s.nodes[size_t(i.node)].name +
                     ": an EXT_mesh_gpu_instancing row times the node's transform is not finite (past a double's range)");
        for (size_t a = 0; a < m_.animations.size(); ++a) add_animation(int(a), out);
        if (skipped_points_lines_ > 0)
            warn(std::to_string(skipped_points_lines_) + " primitive(s) of points or lines skipped (triangles only)");
        if (blended_ > 0) warn(std::to_string(blended_) + " material(s) with alphaMode BLEND drawn opaque");
        if (unused_textures_ > 0)
            warn(std::to_string(unused_textures_) +
                 " normal, occlusion, emissive or metallic-roughness texture(s) not drawn (base colour textures only)");
        out.warnings.insert(out.warnings.begin(), warnings_.begin(), warnings_.end());
        return out;
    }

private:
    void warn(const std::string& what) { warnings_.push_back(file_ + ": warning: " + what); }
    [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, what); }

    // The numbers the shown meshes' primitives hold, each accessor counted
    // once for every primitive that reads it, refused before any is read: a
    // sparse accessor without a buffer view costs the file nothing, but
    // each primitive that shares it is a copy (docs/gltf.md, "Limits").
    void check_geometry_size() const {
        std::vector<bool> shown(m_.meshes.size(), false);
        for (const int n : order_)  // the nodes of the scene shown
            if (const int mesh = m_.nodes[size_t(n)].mesh; mesh >= 0 && size_t(mesh) < shown.size()) shown[size_t(mesh)] = true;
        std::size_t numbers = 0;
        // One accessor past its own limit is left to the read, which names it.
        auto add = [&](int accessor) {
            if (const std::size_t n = read_.values(accessor); n <= kMaxGltfAccessorValues)
                numbers = std::min(numbers + n, kMaxGltfReadValues + 1);
        };
        for (size_t m = 0; m < m_.meshes.size(); ++m) {
            if (!shown[m]) continue;
            for (const tinygltf::Primitive& p : m_.meshes[m].primitives) {
                add(p.indices);
                for (const auto& [name, index] : p.attributes) add(index);
                for (const auto& target : p.targets)
                    for (const auto& [name, index] : target) add(index);
            }
        }
        if (numbers > kMaxGltfReadValues)
            fail("its meshes' accessors hold more than " + std::to_string(kMaxGltfReadValues) +
                 " numbers, counted for each primitive that reads them");
    }

    // The scene's nodes in an order with every parent before its children,
    // each node reached once: a node with two parents, or a cycle, is refused.
    void order_nodes() {
        const size_t n = m_.nodes.size();
        std::vector<int> parent(n, -1);
        for (size_t p = 0; p < n; ++p)
            for (const int c : m_.nodes[p].children) {
                if (c < 0 || size_t(c) >= n) fail("node " + std::to_string(p) + " has child " + std::to_string(c) + ", which does not exist");
                if (parent[size_t(c)] >= 0)
                    fail("node " + std::to_string(c) + " has two parents (" + std::to_string(parent[size_t(c)]) +
                         " and " + std::to_string(p) + ")");
                parent[size_t(c)] = int(p);
            }
        // One parent each, so a cycle is a loop of parents, found anywhere in
        // the file (shown or not): follow each node's parents until a node
        // already followed; one met again on this same walk closes a loop.
        std::vector<int> walked_from(n, -1);
        for (size_t start = 0; start < n; ++start) {
            int x = int(start);
            while (x >= 0 && walked_from[size_t(x)] < 0) {
                walked_from[size_t(x)] = int(start);
                x = parent[size_t(x)];
            }
            if (x >= 0 && walked_from[size_t(x)] == int(start))
                fail("node " + std::to_string(x) + " is its own ancestor (a cycle)");
        }
        std::vector<int> roots;
        if (m_.scenes.empty()) fail("the file has no scene to show (no 'scenes')");
        int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
        if (size_t(scene) >= m_.scenes.size()) fail("scene " + std::to_string(scene) + " does not exist");
        roots = m_.scenes[size_t(scene)].nodes;
        if (roots.empty()) fail("scene " + std::to_string(scene) + " has no nodes: nothing to show");
        new_index_.assign(n, -1);
        std::vector<int> state(n, 0);  // 0 unseen, 1 on the path, 2 done (cycles are refused above)
        std::function<void(int, int)> visit = [&](int node, int depth) {
            if (node < 0 || size_t(node) >= n) fail("scene node " + std::to_string(node) + " does not exist");
            if (state[size_t(node)] == 2) fail("node " + std::to_string(node) + " is reached twice");
            if (depth > 10'000) fail("nodes nested more than 10,000 deep");
            state[size_t(node)] = 1;
            new_index_[size_t(node)] = int(order_.size());
            order_.push_back(node);
            for (const int c : m_.nodes[size_t(node)].children) visit(c, depth + 1);
            state[size_t(node)] = 2;
        };
        for (const int r : roots) {
            if (r >= 0 && size_t(r) < n && parent[size_t(r)] >= 0)
                fail("scene node " + std::to_string(r) + " is also a child of node " + std::to_string(parent[size_t(r)]));
            visit(r, 0);
        }
        parent_ = std::move(parent);
    }

    void add_node(int index, Scene& s) {
        const tinygltf::Node& node = m_.nodes[size_t(index)];
        SceneNode out;
        out.name = node.name.empty() ? "node " + std::to_string(index) : node.name;
        const int p = parent_[size_t(index)];
        out.parent = p >= 0 ? new_index_[size_t(p)] : -1;
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail(out.name + ": 'matrix' needs 16 numbers");
            out.has_matrix = true;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) out.matrix[c][r] = node.matrix[size_t(4 * c + r)];
        } else {
            if (!node.translation.empty() && node.translation.size() != 3) fail(out.name + ": 'translation' needs 3 numbers");
            if (!node.scale.empty() && node.scale.size() != 3) fail(out.name + ": 'scale' needs 3 numbers");
            if (!node.rotation.empty() && node.rotation.size() != 4) fail(out.name + ": 'rotation' needs 4 numbers");
            out.translation = vec3_or(node.translation, dvec3(0));
            out.scale = vec3_or(node.scale, dvec3(1));
            if (node.rotation.size() == 4)
                out.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
        }
        const glm::dmat4 local = out.local();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(local[c][r])) fail(out.name + ": its transform is not finite");
        const int me = int(s.nodes.size());
        s.nodes.push_back(out);
        if (node.mesh >= 0) add_mesh_instances(node, me, s);
        if (node.camera >= 0) add_camera(node.camera, me, s);
        if (const tinygltf::Value* l = extension_value(node.extensions, "KHR_lights_punctual", "light")) {
            if (!l->IsInt()) fail(out.name + ": KHR_lights_punctual's 'light' is not an index");
            add_light(l->GetNumberAsInt(), me, s);
        }
    }

    // The base colour texture and alpha mode of material `mat` (the last
    // of s.materials) onto it (docs/gltf.md, "Textures").
    void add_surface_of(const tinygltf::Material& mat, const std::string& name, Scene& s) {
        Material<double>& out = s.materials.back();
        const auto& pbr = mat.pbrMetallicRoughness;
        if (pbr.baseColorTexture.index >= 0) out.texture = texture_of(pbr.baseColorTexture.index, name, s);
        for (const int t : {pbr.metallicRoughnessTexture.index, mat.normalTexture.index, mat.occlusionTexture.index,
                            mat.emissiveTexture.index})
            unused_textures_ += t >= 0;
        if (mat.alphaMode == "MASK") {
            out.cutout = true;
            out.alpha = pbr.baseColorFactor.size() == 4 ? std::clamp(pbr.baseColorFactor[3], 0.0, 1.0) : 1.0;
            if (!std::isfinite(mat.alphaCutoff) || mat.alphaCutoff < 0) fail(name + ": alphaCutoff must be >= 0");
            out.alpha_cutoff = mat.alphaCutoff;
        } else if (mat.alphaMode == "BLEND") {
            ++blended_;
        } else if (mat.alphaMode != "OPAQUE") {
            fail(name + ": alphaMode '" + mat.alphaMode + "' is not OPAQUE, MASK or BLEND");
        }
    }

    // The scene texture of glTF texture `index`: its image (decoded by
    // gltf_model.cpp) shared with every texture that shows it, and its
    // sampler's wrap modes and magnification filter.
    int texture_of(int index, const std::string& name, Scene& s) {
        if (index < 0 || size_t(index) >= m_.textures.size()) fail(name + ": texture " + std::to_string(index) + " does not exist");
        if (const auto it = textures_.find(index); it != textures_.end()) return it->second;
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
        }
        s.textures.push_back(std::move(out));
        textures_[index] = int(s.textures.size()) - 1;
        return textures_[index];
    }

    // Where EXT_mesh_gpu_instancing puts copies within the node: one matrix
    // a row (T * R * S); none without it (the node itself).
    std::vector<glm::dmat4> rows_of(const tinygltf::Node& node, const std::string& name) const {
        const auto it = node.extensions.find("EXT_mesh_gpu_instancing");
        if (it == node.extensions.end()) return {};
        if (!it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
            fail(name + ": EXT_mesh_gpu_instancing without attributes");
        const tinygltf::Value& attributes = it->second.Get("attributes");
        std::vector<double> t, r, sc;
        size_t rows = 0;
        auto take = [&](const char* key, int components, std::vector<double>& into) {
            if (!attributes.Has(key)) return;
            const tinygltf::Value& v = attributes.Get(key);
            if (!v.IsInt()) fail(name + ": EXT_mesh_gpu_instancing's " + key + " is not an accessor index");
            into = read_.numbers(v.GetNumberAsInt(), components, name + " instancing " + key);
            const size_t n = into.size() / size_t(components);
            if (rows != 0 && n != rows) fail(name + ": EXT_mesh_gpu_instancing's attributes differ in count");
            rows = n;
        };
        take("TRANSLATION", 3, t);
        take("ROTATION", 4, r);
        take("SCALE", 3, sc);
        if (rows > kMaxInstances) fail(name + ": " + std::to_string(rows) + " instances (the limit is " + std::to_string(kMaxInstances) + ")");
        std::vector<glm::dmat4> out;
        for (size_t k = 0; k < rows; ++k) {
            SceneNode row;
            if (!t.empty()) row.translation = {t[3 * k], t[3 * k + 1], t[3 * k + 2]};
            if (!r.empty()) row.rotation = glm::normalize(glm::dquat(r[4 * k + 3], r[4 * k], r[4 * k + 1], r[4 * k + 2]));
            if (!sc.empty()) row.scale = {sc[3 * k], sc[3 * k + 1], sc[3 * k + 2]};
            out.push_back(row.local());
        }
        return out;
    }

    void add_mesh_instances(const tinygltf::Node& node, int at, Scene& s) {
        if (size_t(node.mesh) >= m_.meshes.size()) fail(s.nodes[size_t(at)].name + ": mesh " + std::to_string(node.mesh) + " does not exist");
        const std::vector<glm::dmat4> rows = rows_of(node, s.nodes[size_t(at)].name);
        int first_row = -1;  // the rows are kept once an instance uses them
        const tinygltf::Mesh& mesh = m_.meshes[size_t(node.mesh)];
        // A morphed or skinned mesh is this node's own copy: its pose is the node's.
        const size_t targets = morph_target_count(m_, node.mesh, read_);
        const bool deformed = node.skin >= 0 || targets > 0;
        if (targets > 0) {
            std::vector<double> w = !node.weights.empty() ? node.weights : mesh.weights;
            if (w.empty()) w.assign(targets, 0.0);
            if (w.size() != targets)
                fail(s.nodes[size_t(at)].name + ": " + std::to_string(w.size()) + " morph weights for " +
                     std::to_string(targets) + " targets");
            for (const double x : w)
                if (!std::isfinite(x)) fail(s.nodes[size_t(at)].name + ": a morph weight is not finite");
            s.nodes[size_t(at)].weights = std::move(w);
        }
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            int sm = scene_mesh(node.mesh, int(p), s);
            if (sm < 0) continue;
            if (deformed) sm = add_deformation(node, at, node.mesh, int(p), sm, s);
            const int material = mesh.primitives[p].material;
            if (material >= int(m_.materials.size())) fail("mesh " + std::to_string(node.mesh) + ": material " + std::to_string(material) + " does not exist");
            if (!rows.empty() && first_row < 0) {
                first_row = int(s.instance_rows.size());
                s.instance_rows.insert(s.instance_rows.end(), rows.begin(), rows.end());
            }
            for (size_t k = 0; k < std::max<size_t>(rows.size(), 1); ++k) {
                if (s.instances.size() >= kMaxInstances) fail("more than " + std::to_string(kMaxInstances) + " instances");
                s.instances.push_back({sm, material >= 0 ? material : default_material_, glm::dmat4(1.0), at,
                                       first_row < 0 ? -1 : first_row + int(k)});
            }
        }
    }

    // Node `at`'s own copy of a morphed or skinned primitive (its scene mesh
    // `shared` as the rest pose), with how it deforms; returns the copy's
    // scene mesh.
    int add_deformation(const tinygltf::Node& node, int at, int m, int p, int shared, Scene& s) {
        const tinygltf::Primitive& prim = m_.meshes[size_t(m)].primitives[size_t(p)];
        const std::string what = "mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " on " + s.nodes[size_t(at)].name;
        Deformation d;
        d.rest = s.meshes[size_t(shared)].mesh;
        d.node = at;
        d.mesh = int(s.meshes.size());
        const size_t vertices = d.rest->positions.size();
        // Each node deforms its own copy: bounded, as a file of many nodes
        // sharing one big morphed mesh would otherwise copy it for each.
        deformed_vertices_ += vertices;
        if (deformed_vertices_ > kMaxGltfDeformedVertices)
            fail(what + ": morphed and skinned copies of more than " + std::to_string(kMaxGltfDeformedVertices) +
                 " vertices in all (the limit)");
        // Read once per primitive (and skin), shared by every node using it.
        auto& targets = targets_[{m, p}];
        if (!targets && !prim.targets.empty())
            targets = std::make_shared<const std::vector<MorphTarget>>(read_morph_targets(prim, read_, vertices, what));
        d.targets = targets;
        if (node.skin >= 0) {
            if (size_t(node.skin) >= m_.skins.size()) fail(what + ": skin " + std::to_string(node.skin) + " does not exist");
            const tinygltf::Skin& skin = m_.skins[size_t(node.skin)];
            for (const int j : skin.joints) {
                if (j < 0 || size_t(j) >= m_.nodes.size()) fail(what + ": joint node " + std::to_string(j) + " does not exist");
                if (new_index_[size_t(j)] < 0) fail(what + ": joint node " + std::to_string(j) + " is not in the scene shown");
                d.skin.joints.push_back(new_index_[size_t(j)]);
            }
            d.skin.inverse_binds = read_inverse_binds(skin, read_, what);
            auto& weights = skin_weights_[{m, p, node.skin}];
            if (!weights)
                weights = std::make_shared<const SkinWeights>(
                    read_skin_weights(prim, read_, vertices, skin.joints.size(), what));
            d.skin.weights = weights;
        }
        s.meshes.push_back({s.meshes[size_t(shared)].name + " on " + s.nodes[size_t(at)].name, d.rest});
        s.deformations.push_back(std::move(d));
        return int(s.meshes.size()) - 1;
    }

    // The scene mesh of mesh m's primitive p, read once; -1 for a primitive
    // of points or lines.
    int scene_mesh(int m, int p, Scene& s) {
        const auto key = std::make_pair(m, p);
        const auto it = meshes_.find(key);
        if (it != meshes_.end()) return it->second;
        const tinygltf::Primitive& prim = m_.meshes[size_t(m)].primitives[size_t(p)];
        const std::string what = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
        check_primitive(prim, what);
        int result = -1;
        if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP) {
            ++skipped_points_lines_;
        } else if (prim.mode < TINYGLTF_MODE_TRIANGLES || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
            fail(what + ": mode " + std::to_string(prim.mode) + " is not glTF's");
        } else {
            result = int(s.meshes.size());
            Mesh mesh = read_primitive(prim, what);
            mesh.uvs = read_uvs(prim, what);
            s.meshes.push_back({what, std::make_shared<Mesh>(std::move(mesh))});
        }
        meshes_[key] = result;
        return result;
    }

    // What the specification asks of every primitive, drawn or not: its
    // attributes' accessors as many as POSITION's, a vertex count its mode
    // can use (a multiple of 3 for triangles, of 2 for lines), and every
    // texture coordinate set its material reads.
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
        for (const int set : {mat.pbrMetallicRoughness.baseColorTexture.index >= 0 ? base_color_set(mat) : -1,
                              mat.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0 ? mat.pbrMetallicRoughness.metallicRoughnessTexture.texCoord : -1,
                              mat.normalTexture.index >= 0 ? mat.normalTexture.texCoord : -1,
                              mat.occlusionTexture.index >= 0 ? mat.occlusionTexture.texCoord : -1,
                              mat.emissiveTexture.index >= 0 ? mat.emissiveTexture.texCoord : -1})
            if (set >= 0 && !prim.attributes.count("TEXCOORD_" + std::to_string(set)))
                fail(what + ": its material reads TEXCOORD_" + std::to_string(set) + ", which it does not have");
    }

    // The TEXCOORD set a material's base colour texture reads: its own,
    // or its KHR_texture_transform's texCoord, which overrides it.
    static int base_color_set(const tinygltf::Material& mat) {
        const tinygltf::TextureInfo& info = mat.pbrMetallicRoughness.baseColorTexture;
        if (const tinygltf::Value* t = extension_value(info.extensions, "KHR_texture_transform", "texCoord"))
            if (t->IsInt()) return t->GetNumberAsInt();
        return info.texCoord;
    }

    // The texture coordinates the primitive's base colour texture reads
    // (TEXCOORD_n, n from the texture or its KHR_texture_transform), moved
    // by that transform: uv' = translate(offset) rotate(rotation) scale(scale) uv.
    // Empty when its material has no such texture.
    std::vector<dvec2> read_uvs(const tinygltf::Primitive& prim, const std::string& what) const {
        if (prim.material < 0 || size_t(prim.material) >= m_.materials.size()) return {};
        const tinygltf::TextureInfo& info = m_.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorTexture;
        if (info.index < 0) return {};
        int set = info.texCoord;
        dvec2 offset(0), scale(1);
        double rotation = 0;
        if (const auto it = info.extensions.find("KHR_texture_transform"); it != info.extensions.end()) {
            const tinygltf::Value& x = it->second;
            auto pair = [&](const char* key, dvec2& into) {
                if (!x.Has(key)) return;
                const tinygltf::Value& v = x.Get(key);
                if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
                    fail(what + ": KHR_texture_transform's " + key + " needs 2 numbers");
                into = {v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble()};
            };
            pair("offset", offset);
            pair("scale", scale);
            if (x.Has("rotation")) {
                if (!x.Get("rotation").IsNumber()) fail(what + ": KHR_texture_transform's rotation is not a number");
                rotation = x.Get("rotation").GetNumberAsDouble();
            }
            if (x.Has("texCoord")) {
                if (!x.Get("texCoord").IsInt() || x.Get("texCoord").GetNumberAsInt() < 0)
                    fail(what + ": KHR_texture_transform's texCoord is not a set index");
                set = x.Get("texCoord").GetNumberAsInt();
            }
            if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation))
                fail(what + ": KHR_texture_transform's numbers are not finite");
        }
        const auto attribute = prim.attributes.find("TEXCOORD_" + std::to_string(set));
        if (attribute == prim.attributes.end())
            fail(what + ": its material reads TEXCOORD_" + std::to_string(set) + ", which it does not have");
        const std::vector<double> t = read_.numbers(attribute->second, 2, what + " TEXCOORD_" + std::to_string(set));
        const double c = std::cos(rotation), sn = std::sin(rotation);
        std::vector<dvec2> uvs(t.size() / 2);
        for (size_t i = 0; i < uvs.size(); ++i) {
            const double u = scale.x * t[2 * i], v = scale.y * t[2 * i + 1];
            uvs[i] = {c * u + sn * v + offset.x, -sn * u + c * v + offset.y};
            if (!std::isfinite(uvs[i].x) || !std::isfinite(uvs[i].y))
                fail(what + ": KHR_texture_transform takes TEXCOORD_" + std::to_string(set) + " " +
                     std::to_string(i) + " past a double's range");
        }
        return uvs;
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

    void add_camera(int index, int node, Scene& s) const {
        if (index < 0 || size_t(index) >= m_.cameras.size()) fail("camera " + std::to_string(index) + " does not exist");
        s.cameras.push_back(gltf_camera(m_.cameras[size_t(index)], index, node, file_));
    }

    void add_light(int index, int node, Scene& s) const {
        if (index < 0 || size_t(index) >= m_.lights.size()) fail("light " + std::to_string(index) + " does not exist");
        add_gltf_light(m_.lights[size_t(index)], index, node, exposure_, s, file_);
    }

    void add_animation(int index, GltfFile& out) {
        out.animations.push_back(read_gltf_animation(m_, index, read_, new_index_, out.scene.nodes));
    }

    const tinygltf::Model& m_;
    std::string file_;
    AccessorReader read_;
    double exposure_;
    std::vector<int> parent_, new_index_, order_;
    std::map<std::pair<int, int>, int> meshes_;
    int default_material_ = 0;
    int skipped_points_lines_ = 0;
    int blended_ = 0, unused_textures_ = 0;
    std::map<int, int> textures_;  // glTF texture -> Scene::textures
    std::map<int, std::shared_ptr<const TextureImage>> images_;  // glTF image, decoded
    size_t deformed_vertices_ = 0;
    std::map<std::pair<int, int>, std::shared_ptr<const std::vector<MorphTarget>>> targets_;
    std::map<std::tuple<int, int, int>, std::shared_ptr<const SkinWeights>> skin_weights_;
    std::vector<std::string> warnings_;
};

}  // namespace

bool is_gltf_file(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".gltf" || ext == ".glb";
}

GltfFile load_gltf_from_memory(const std::string& bytes, const std::string& file, const std::string& folder,
                               double exposure) {
    std::vector<std::string> warnings;
    const tinygltf::Model model = parse_gltf_model(bytes, file, folder, warnings);
    GltfFile out = Converter(model, file, exposure).convert();
    out.warnings.insert(out.warnings.end(), warnings.begin(), warnings.end());
    return out;
}

GltfFile load_gltf(const std::string& path, double exposure) {
    std::vector<std::string> warnings;
    const tinygltf::Model model = read_gltf_model(path, warnings);
    GltfFile out = Converter(model, path, exposure).convert();
    out.warnings.insert(out.warnings.end(), warnings.begin(), warnings.end());
    return out;
}

std::vector<NodeAnimation> add_gltf(Scene& scene, GltfFile file, const std::string& name, const Transform& transform,
                                    int parent) {
    Scene& g = file.scene;
    const int materials = int(scene.materials.size()), meshes = int(scene.meshes.size()),
              nodes = int(scene.nodes.size()), textures = int(scene.textures.size());
    // The placement, and inside it glTF's y-up turned to firsthit's z-up.
    scene.groups.push_back({name, transform, parent});
    Transform up;
    up.axis = {1, 0, 0};
    up.radians = std::numbers::pi / 2;
    scene.groups.push_back({name + " (y-up)", up, int(scene.groups.size()) - 1});
    const int top = int(scene.groups.size()) - 1;
    for (size_t m = 0; m < g.materials.size(); ++m) {
        scene.material_names.push_back(name + "/" + g.material_names[m]);
        scene.materials.push_back(g.materials[m]);
        if (scene.materials.back().texture >= 0) scene.materials.back().texture += textures;
    }
    scene.textures.insert(scene.textures.end(), g.textures.begin(), g.textures.end());
    for (SceneMesh& m : g.meshes) scene.meshes.push_back({name + "/" + m.name, std::move(m.mesh)});
    for (SceneNode n : g.nodes) {
        if (n.parent >= 0) n.parent += nodes;
        else n.group = top;
        scene.nodes.push_back(std::move(n));
    }
    for (Instance i : g.instances) {
        i.mesh += meshes;
        i.material += materials;
        i.node += nodes;
        if (i.row >= 0) i.row += int(scene.instance_rows.size());
        scene.instances.push_back(i);
    }
    scene.instance_rows.insert(scene.instance_rows.end(), g.instance_rows.begin(), g.instance_rows.end());
    // What hangs on a node, its node renumbered.
    auto add_on_nodes = [&](const auto& from, auto& to) {
        for (auto x : from) {
            x.node += nodes;
            to.push_back(x);
        }
    };
    add_on_nodes(g.cameras, scene.cameras);
    add_on_nodes(g.directional_lights, scene.directional_lights);
    add_on_nodes(g.spot_lights, scene.spot_lights);
    for (Deformation d : g.deformations) {
        d.mesh += meshes;
        d.node += nodes;
        for (int& j : d.skin.joints) j += nodes;
        scene.deformations.push_back(std::move(d));
    }
    for (NodeAnimation& a : file.animations)
        for (NodeChannel& c : a.channels) c.node += nodes;
    place_nodes(scene);
    deform_meshes(scene);  // the pose the file stands in
    return std::move(file.animations);
}

}  // namespace fh
