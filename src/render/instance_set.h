// Instances as the tracer reads them -- the second level of a two-level BVH.
// Each distinct mesh is flattened once, in its own space, with its own BVH
// (a FlatGeometry of triangles: the same builder, blocks and packet walk as
// the world's); each instance keeps only its matrices; a BVH over the
// instances' world boxes finds which a packet may meet. A ray enters an
// instance by its inverse transform -- a packet stays a packet -- so moving
// an instance touches its matrices and the top BVH, never a triangle.
//
// In instance space a ray's direction is made unit again (the triangle test
// needs that); its distances there are `scale` times the world's, scale
// being the length of the direction before that. Each ray's nearest hit is
// carried across as t_world = t_object / scale.
#pragma once

#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>

#include "render/cutouts.h"
#include "render/flat_geometry.h"

namespace fh {

class ThreadPool;

// p -> linear p + offset, the columns of a 3x4 matrix in T.
template <typename T>
struct AffineMap {
    Vec3<T> x, y, z;  // the images of the axes
    Vec3<T> offset;

    static AffineMap from(const glm::dmat4& m) {
        return {Vec3<T>(dvec3(m[0])), Vec3<T>(dvec3(m[1])), Vec3<T>(dvec3(m[2])), Vec3<T>(dvec3(m[3]))};
    }
    FH_HOT_INLINE Vec3Lanes<T> vector(const Vec3Lanes<T>& v) const { return v.x * x + v.y * y + v.z * z; }
    FH_HOT_INLINE Vec3Lanes<T> point(const Vec3Lanes<T>& p) const { return vector(p) + offset; }
};

template <typename T>
struct FlatInstance {
    AffineMap<T> to_object;  // world -> the mesh's space
    AffineMap<T> to_world;   // and back (shading)
    AffineMap<T> normal_to_world;  // the inverse transpose of to_world's linear part (offset 0)
    int mesh = 0;
    int material = 0;
    int cutout = -1;  // into InstanceSet::cutouts: its material is MASKed or BLENDed; -1: solid

    // The rays of a packet in the mesh's space, with unit directions, and
    // each ray's scale (object distance per world distance).
    FH_HOT_INLINE RayPacket<T> enter(const RayPacket<T>& ray, Lanes<T>& scale) const {
        const Vec3Lanes<T> d = to_object.vector(ray.direction);
        scale = sqrt(dot(d, d));
        return {to_object.point(ray.origin), d * (T(1) / scale)};
    }
};

template <typename T>
struct InstanceSet {
    // By Scene::meshes: each mesh's triangles in its own space, flattened
    // once and shared by every frame (nullptr for a mesh nothing places).
    std::vector<std::shared_ptr<const FlatGeometry<T>>> meshes;
    std::vector<Aabb> mesh_boxes;  // by Scene::meshes, in the mesh's space
    BigArray<FlatInstance<T>> instances;
    std::vector<Aabb> instance_boxes;  // by instance, in world space (the top BVH's input)
    std::vector<Cutout> cutouts;  // the MASKed and BLENDed materials' (render/cutouts.h)
    Bvh bvh;  // over the instances' world boxes (a leaf: one instance)
    BigArray<WalkNode<T>> walk_nodes;
    std::vector<std::int32_t> walk_from;  // each walk node's BVH node (walk_nodes_of)

    bool empty() const { return instances.empty(); }

    // The scene's instances; nullptr when it has none. pool: builds on it.
    static std::shared_ptr<const InstanceSet> build(const Scene& scene, ThreadPool* pool = nullptr);
    // The same meshes with the instances where `moved` places them (a
    // movie's frame): only matrices, boxes and the top BVH are redone, and
    // the trees of the meshes it deforms refitted. `previous` itself when
    // nothing moved or deforms: its top BVH is not refitted.
    static std::shared_ptr<const InstanceSet> moved(const std::shared_ptr<const InstanceSet>& previous,
                                                    const Scene& moved, ThreadPool* pool = nullptr);
};

extern template struct InstanceSet<float>;
extern template struct InstanceSet<double>;

}  // namespace fh
