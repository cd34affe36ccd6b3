#include "render/instance_set.h"

#include <chrono>

#include <glm/gtc/matrix_inverse.hpp>

namespace fh {

namespace {

// A mesh's triangles in its own space, as a scene of their own.
Scene mesh_scene(const Mesh& mesh) {
    Scene s;
    PlacedMesh placed = place(mesh, glm::dmat4(1.0));
    s.triangles = std::move(placed.triangles);
    s.vertex_normals = std::move(placed.vertex_normals);
    return s;
}

// The box around the mesh's positions placed by `to_world`: its eight
// corners carried over, padded like every primitive's box (flat_geometry).
Aabb world_box(const Aabb& object, const glm::dmat4& to_world) {
    Aabb b;
    for (int c = 0; c < 8; ++c) {
        const dvec3 corner((c & 1) ? object.hi.x : object.lo.x, (c & 2) ? object.hi.y : object.lo.y,
                           (c & 4) ? object.hi.z : object.lo.z);
        b.grow(dvec3(to_world * glm::dvec4(corner, 1.0)));
    }
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

template <typename T>
FlatInstance<T> flat_instance(const Instance& i) {
    const glm::dmat4 inverse = glm::inverse(i.to_world);
    const glm::dmat3 normals = glm::inverseTranspose(glm::dmat3(i.to_world));
    FlatInstance<T> f;
    f.to_object = AffineMap<T>::from(inverse);
    f.to_world = AffineMap<T>::from(i.to_world);
    f.normal_to_world = AffineMap<T>::from(glm::dmat4(normals));
    f.mesh = i.mesh;
    f.material = i.material;
    return f;
}

// The instances' matrices and boxes, and the top BVH: built anew, or (same
// count) refitted over the tree `previous` has.
template <typename T>
void place_instances(const Scene& scene, const std::vector<Aabb>& mesh_boxes, const Bvh* previous,
                     InstanceSet<T>& set, ThreadPool* pool) {
    const auto start = std::chrono::steady_clock::now();
    set.instances.clear();
    set.instances.reserve(scene.instances.size());
    std::vector<Aabb> boxes;
    boxes.reserve(scene.instances.size());
    for (const Instance& i : scene.instances) {
        set.instances.push_back(flat_instance<T>(i));
        boxes.push_back(world_box(mesh_boxes[size_t(i.mesh)], i.to_world));
    }
    if (previous && previous->prims.size() == boxes.size()) {
        set.bvh = *previous;
        refit_bvh(set.bvh, boxes);
    } else {
        set.bvh = build_bvh(boxes, pool, 1);
    }
    // Every leaf lists its instance (no triangle runs at this level).
    set.walk_nodes = walk_nodes_of<T>(set.bvh, PrimitiveIds{int(boxes.size()), 0, 0});
    set.update_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
    place_instances(scene, set->mesh_boxes, nullptr, *set, pool);
    return set;
}

template <typename T>
std::shared_ptr<const InstanceSet<T>> InstanceSet<T>::moved(const Scene& moved, ThreadPool* pool) const {
    auto set = std::make_shared<InstanceSet<T>>();
    set->meshes = meshes;
    set->mesh_boxes = mesh_boxes;
    place_instances(moved, set->mesh_boxes, &bvh, *set, pool);
    return set;
}

template struct InstanceSet<float>;
template struct InstanceSet<double>;

}  // namespace fh
