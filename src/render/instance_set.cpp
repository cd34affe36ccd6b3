#include "render/instance_set.h"

#include <cstring>

#include "scene/mesh_tangents.h"

namespace fh {

namespace {

// A mesh's triangles in its own space, as a scene of their own, with their
// texture coordinates, tangents and vertex colours.
Scene mesh_scene(const Mesh& mesh) {
    Scene s;
    PlacedMesh placed = place(mesh, glm::dmat4(1.0));
    s.triangles = std::move(placed.triangles);
    s.vertex_normals = std::move(placed.vertex_normals);
    if (!mesh.uvs.empty()) {
        s.triangle_uvs.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles) s.triangle_uvs.push_back({mesh.uvs[t[0]], mesh.uvs[t[1]], mesh.uvs[t[2]]});
    }
    if (!mesh.tangents.empty()) {
        s.triangle_tangents.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles)
            s.triangle_tangents.push_back({mesh.tangents[t[0]], mesh.tangents[t[1]], mesh.tangents[t[2]]});
    } else if (mesh.make_tangents) {
        s.triangle_tangents = corner_tangents(mesh);
    }
    if (!mesh.colors.empty()) {
        s.triangle_colors.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles)
            s.triangle_colors.push_back({mesh.colors[t[0]], mesh.colors[t[1]], mesh.colors[t[2]]});
    }
    if (!mesh.alphas.empty()) {
        s.triangle_alphas.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles)
            s.triangle_alphas.push_back({mesh.alphas[t[0]], mesh.alphas[t[1]], mesh.alphas[t[2]]});
    }
    return s;
}

// The box around a box placed by `to_world`: its centre carried over, its
// half-extent through the absolute values of the linear part (the eight
// corners' box, to rounding), padded like every primitive's box.
Aabb world_box(const Aabb& object, const glm::dmat4& to_world) {
    const dvec3 center = object.center(), half = 0.5 * (object.hi - object.lo);
    const dvec3 c = dvec3(to_world * glm::dvec4(center, 1.0));
    const glm::dmat3 a(to_world);
    const dvec3 e = glm::abs(a[0]) * half.x + glm::abs(a[1]) * half.y + glm::abs(a[2]) * half.z;
    Aabb b{c - e, c + e};
    const double pad = 1e-5 * (glm::length(b.hi - b.lo) + std::max(glm::length(b.lo), glm::length(b.hi)));
    b.lo -= pad;
    b.hi += pad;
    return b;
}

Aabb mesh_box(const Mesh& mesh) {
    Aabb b;
    for (const dvec3& p : mesh.positions) b.grow(p);
    return b;
}

// An instance's maps in T. One 3 x 3 inverse serves both ways: the inverse
// of p -> A p + b is p -> A^-1 (p - b), and normals go by A^-T.
template <typename T>
FlatInstance<T> flat_instance(const Instance& i, int cutout) {
    const glm::dmat3 a(i.to_world);
    const glm::dmat3 inverse = glm::inverse(a);
    const dvec3 b(i.to_world[3]);
    glm::dmat4 to_object(inverse);
    to_object[3] = glm::dvec4(-(inverse * b), 1.0);
    FlatInstance<T> f;
    f.to_object = AffineMap<T>::from(to_object);
    f.to_world = AffineMap<T>::from(i.to_world);
    f.normal_to_world = AffineMap<T>::from(glm::dmat4(glm::transpose(inverse)));
    f.mesh = i.mesh;
    f.material = i.material;
    f.cutout = cutout;
    return f;
}

// The scene's instances in T, each with its index into set.cutouts (filled
// here: one a MASKed or BLENDed material).
template <typename T>
void flatten_instances(const Scene& scene, InstanceSet<T>& set) {
    std::vector<int> cutout_of(scene.materials.size(), -1);
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const Material<double>& mat = scene.materials[m];
        if (!mat.cutout && !mat.blend) continue;
        cutout_of[m] = int(set.cutouts.size());
        set.cutouts.push_back({mat.texture >= 0 ? scene.textures[size_t(mat.texture)] : Texture{}, float(mat.alpha),
                               mat.blend ? 0.5f : float(mat.alpha_cutoff), mat.blend});
    }
    set.instances.reserve(scene.instances.size());
    for (const Instance& i : scene.instances) set.instances.push_back(flat_instance<T>(i, cutout_of[size_t(i.material)]));
}

// The instances' world boxes and the top BVH over them: built anew, or
// (same count) refitted over the tree `previous` has, whose boxes serve the
// instances `kept` marks (the same maps in T, the same mesh box).
template <typename T>
void fit_top_level(const Scene& scene, const InstanceSet<T>* previous, const std::vector<bool>& kept,
                   InstanceSet<T>& set, ThreadPool* pool) {
    set.instance_boxes.resize(scene.instances.size());
    for (size_t k = 0; k < scene.instances.size(); ++k) {
        const Instance& i = scene.instances[k];
        set.instance_boxes[k] = kept.empty() || !kept[k] ? world_box(set.mesh_boxes[size_t(i.mesh)], i.to_world)
                                                         : previous->instance_boxes[k];
    }
    if (previous && previous->bvh.prims.size() == set.instance_boxes.size()) {
        set.bvh = previous->bvh;
        refit_bvh(set.bvh, set.instance_boxes);
        set.walk_nodes = previous->walk_nodes;
        set.walk_from = previous->walk_from;
        refit_walk_boxes(set.walk_nodes, set.bvh, set.walk_from);
    } else {
        set.bvh = build_bvh(set.instance_boxes, pool, 1);
        // Every leaf lists its instance (no triangle runs at this level).
        set.walk_nodes = walk_nodes_of<T>(set.bvh, PrimitiveIds{int(set.instance_boxes.size()), 0, 0}, &set.walk_from);
    }
}

// The same bits, not just equal values: a -0 where a +0 was turns a ray
// direction's reciprocal from +inf to -inf.
template <typename T>
bool same_bits(const FlatInstance<T>& a, const FlatInstance<T>& b) {
    return std::memcmp(&a.to_object, &b.to_object, 3 * sizeof(AffineMap<T>)) == 0 && a.mesh == b.mesh &&
           a.material == b.material && a.cutout == b.cutout;
}

std::vector<Aabb> boxes_of_meshes(const Scene& scene) {
    std::vector<Aabb> boxes;
    for (const SceneMesh& m : scene.meshes) boxes.push_back(mesh_box(*m.mesh));
    return boxes;
}

}  // namespace

template <typename T>
std::shared_ptr<const InstanceSet<T>> InstanceSet<T>::build(const Scene& scene, ThreadPool* pool) {
    if (scene.instances.empty()) return nullptr;
    auto set = std::make_shared<InstanceSet<T>>();
    std::vector<bool> used(scene.meshes.size(), false);
    for (const Instance& i : scene.instances) used[size_t(i.mesh)] = true;
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        set->meshes.push_back(used[m] ? std::make_shared<const FlatGeometry<T>>(
                                            FlatGeometry<T>::build(mesh_scene(*scene.meshes[m].mesh), pool))
                                      : nullptr);
    set->mesh_boxes = boxes_of_meshes(scene);
    flatten_instances(scene, *set);
    fit_top_level<T>(scene, nullptr, {}, *set, pool);
    return set;
}

template <typename T>
std::shared_ptr<const InstanceSet<T>> InstanceSet<T>::moved(const std::shared_ptr<const InstanceSet>& previous,
                                                            const Scene& moved, ThreadPool* pool) {
    // A movie's instances stand still between its keys, or until its wave
    // reaches them: nothing to refit then. Each instance is flattened once,
    // and one whose maps in T kept their bits keeps its box. (A material's cutout
    // cannot be animated, so each instance's index into the cutouts stays.)
    const BigArray<FlatInstance<T>>& before = previous->instances;
    auto set = std::make_shared<InstanceSet<T>>();
    std::vector<bool> kept;
    if (moved.instances.size() == before.size()) {
        set->cutouts = previous->cutouts;
        set->instances.reserve(before.size());
        kept.resize(before.size());
        bool still = moved.deformations.empty();
        for (size_t k = 0; k < before.size(); ++k) {
            set->instances.push_back(flat_instance<T>(moved.instances[k], before[k].cutout));
            kept[k] = same_bits(set->instances[k], before[k]);
            still = still && kept[k];
        }
        if (still) return previous;
    } else {
        flatten_instances(moved, *set);
    }
    set->meshes = previous->meshes;
    set->mesh_boxes = previous->mesh_boxes;
    // Morphed and skinned meshes: the same triangles moved, so the same
    // tree with its boxes refitted (scene/deformation.h); their instances'
    // boxes are placed anew.
    for (const Deformation& d : moved.deformations) {
        const size_t m = size_t(d.mesh);
        if (!set->meshes[m]) continue;
        const Mesh& mesh = *moved.meshes[m].mesh;
        set->meshes[m] = std::make_shared<const FlatGeometry<T>>(set->meshes[m]->refit(mesh_scene(mesh), pool));
        set->mesh_boxes[m] = mesh_box(mesh);
    }
    if (!moved.deformations.empty()) kept.clear();
    fit_top_level(moved, previous.get(), kept, *set, pool);
    return set;
}

template struct InstanceSet<float>;
template struct InstanceSet<double>;

}  // namespace fh
