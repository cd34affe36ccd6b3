#include "gltf/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <tuple>

#include "files/file_names.h"
#include "gltf/accessors.h"
#include "gltf/gltf_animations.h"
#include "gltf/gltf_cameras_lights.h"
#include "gltf/gltf_deform.h"
#include "gltf/gltf_materials.h"
#include "gltf/gltf_nodes.h"
#include "gltf/gltf_primitives.h"
#include "text/input_error.h"

namespace fh {

namespace {

class Converter {
public:
    Converter(const tinygltf::Model& model, std::string file, double exposure)
        : m_(model), file_(std::move(file)), read_(model, file_), exposure_(exposure) {}

    GltfFile convert() {
        GltfFile out;
        Scene& s = out.scene;
        const GltfMaterialsAdded materials = add_gltf_materials(m_, file_, s);
        default_material_ = materials.default_material;
        GltfNodeOrder order = order_gltf_nodes(m_, file_);
        order_ = std::move(order.order);
        new_index_ = std::move(order.new_index);
        parent_ = std::move(order.parent);
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
        if (materials.unused_textures > 0)
            warn(std::to_string(materials.unused_textures) +
                 " texture(s) not drawn (emissive, occlusion, normal or metallic-roughness textures on other "
                 "coordinates than their mesh carries)");
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

    void add_node(int index, Scene& s) {
        const tinygltf::Node& node = m_.nodes[size_t(index)];
        SceneNode out = gltf_scene_node(node, index, file_);
        const int p = parent_[size_t(index)];
        out.parent = p >= 0 ? new_index_[size_t(p)] : -1;
        const int me = int(s.nodes.size());
        s.nodes.push_back(out);
        if (node.mesh >= 0) add_mesh_instances(node, me, s);
        if (node.camera >= 0) add_camera(node.camera, me, s);
        if (const tinygltf::Value* l = extension_value(node.extensions, "KHR_lights_punctual", "light")) {
            if (!l->IsInt()) fail(out.name + ": KHR_lights_punctual's 'light' is not an index");
            add_light(l->GetNumberAsInt(), me, s);
        }
    }

    void add_mesh_instances(const tinygltf::Node& node, int at, Scene& s) {
        if (size_t(node.mesh) >= m_.meshes.size()) fail(s.nodes[size_t(at)].name + ": mesh " + std::to_string(node.mesh) + " does not exist");
        const std::vector<glm::dmat4> rows = gltf_instancing_rows(node, read_, s.nodes[size_t(at)].name);
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
        check_gltf_primitive(m_, read_, prim, what);
        int result = -1;
        if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP) {
            ++skipped_points_lines_;
        } else if (prim.mode < TINYGLTF_MODE_TRIANGLES || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
            fail(what + ": mode " + std::to_string(prim.mode) + " is not glTF's");
        } else {
            result = int(s.meshes.size());
            s.meshes.push_back({what, std::make_shared<Mesh>(read_gltf_primitive(m_, read_, prim, what))});
        }
        meshes_[key] = result;
        return result;
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
    size_t deformed_vertices_ = 0;
    std::map<std::pair<int, int>, std::shared_ptr<const std::vector<MorphTarget>>> targets_;
    std::map<std::tuple<int, int, int>, std::shared_ptr<const SkinWeights>> skin_weights_;
    std::vector<std::string> warnings_;
};

}  // namespace

bool is_gltf_file(const std::string& path) {
    const std::string ext = lowercase_extension(path);
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
        for (int* t : {&scene.materials.back().texture, &scene.materials.back().emissive_texture,
                       &scene.materials.back().occlusion_texture, &scene.materials.back().normal_texture,
                       &scene.materials.back().metal_rough_texture})
            if (*t >= 0) *t += textures;
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