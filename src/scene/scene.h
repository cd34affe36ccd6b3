// The scene as a file describes it (report sections 3-7): surfaces, materials,
// lights and cameras, in double precision. How to render it (quality, effects)
// travels beside it in RenderSettings (render/settings.h). The tracer builds
// its own flat copy in its scalar type (render/flat_scene.h).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geometry/plane.h"
#include "geometry/shapes.h"
#include "geometry/triangle.h"
#include "scene/camera.h"
#include "scene/deformation.h"
#include "scene/instance.h"
#include "scene/lights.h"
#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/node.h"
#include "scene/spot_light.h"
#include "scene/texture.h"

namespace fh {

enum class SurfaceKind { sphere, plane, triangle, mesh, instance, instances, group };

// A surface the file names (`name:`), which a movie can address to animate
// it, or any surface inside a group (name empty), which moves with it.
struct NamedSurface {
    std::string name;
    SurfaceKind kind = SurfaceKind::sphere;
    bool colored_mesh = false;  // a `type: mesh` with vertex colours, kept as an instance (messages say "mesh")
    // sphere, plane: into spheres or planes; triangle, mesh: its first
    // triangle; instance, instances: its first instance; group: into groups.
    size_t index = 0;
    size_t count = 1;  // triangle, mesh, instances: its triangles (a mesh's kept on loading) or instances
    Transform transform;               // triangle, mesh, instance(s), group: as the file gives it
    std::shared_ptr<const Mesh> mesh;  // triangle, mesh: in its own space
    int group = -1;                    // the group it is in (-1: none); its values are in that group's space
    // In its group's space (group >= 0): a sphere's or plane's own values;
    // an `instances` set's rows (named or in a group), before its transform.
    Sphere<double> local_sphere{};
    Plane<double> local_plane{};
    std::shared_ptr<const std::vector<glm::dmat4>> local_placements;
};

struct Scene {
    std::vector<std::string> material_names;  // parallel to materials
    std::vector<Material<double>> materials;
    std::vector<Texture> textures;  // what materials' `texture` indexes
    BoundedShapes<double> shapes;  // spheres and any other bounded shape (geometry/shapes.h)
    std::vector<Plane<double>> planes;
    std::vector<Triangle<double>> triangles;
    // Empty, or one per triangle: the vertex normals smooth shading
    // interpolates (all three zero: the triangle is shaded flat).
    std::vector<std::array<dvec3, 3>> vertex_normals;
    // Empty, or one per triangle: its vertices' texture coordinates (an
    // instance's mesh, render/instance_set.cpp).
    std::vector<std::array<dvec2, 3>> triangle_uvs;
    // Empty, or one per triangle: its vertices' tangents (the same).
    std::vector<std::array<glm::dvec4, 3>> triangle_tangents;
    // Empty, or one per triangle: its vertices' colours (the same).
    std::vector<std::array<dvec3, 3>> triangle_colors;
    // Empty, or one per triangle: its vertices' alphas (the same).
    std::vector<std::array<double, 3>> triangle_alphas;
    std::vector<AmbientLight<double>> ambient_lights;  // at most one
    std::vector<DirectionalLight<double>> directional_lights;
    std::vector<SpotLight<double>> spot_lights;
    std::vector<Camera> cameras;
    std::vector<NamedSurface> named_surfaces;
    std::vector<SceneMesh> meshes;   // the `meshes:` section, each file read once
    std::vector<Instance> instances;  // of those meshes
    std::vector<glm::dmat4> instance_rows;  // glTF instances' places in their nodes (Instance::row)
    std::vector<Group> groups;
    std::vector<SceneNode> nodes;  // glTF files' nodes, parents first (scene/node.h)
    std::vector<Deformation> deformations;  // meshes morphed or skinned (scene/deformation.h)
    int mesh_files = 0;                    // mesh files read (each once)
    size_t degenerate_mesh_triangles = 0;  // their zero-area triangles, left out

    std::vector<Sphere<double>>& spheres() { return shapes.of<Sphere>(); }
    const std::vector<Sphere<double>>& spheres() const { return shapes.of<Sphere>(); }

    const Camera* find_camera(const std::string& name) const {
        for (const Camera& c : cameras)
            if (c.name == name) return &c;
        return nullptr;
    }
    const NamedSurface* find_surface(const std::string& name) const {
        for (const NamedSurface& s : named_surfaces)
            if (s.name == name) return &s;
        return nullptr;
    }
};

// A named triangle or mesh placed anew by `transform`: its triangles (and
// vertex normals) in the scene replaced, one for one.
void place_surface(Scene& scene, const NamedSurface& surface, const Transform& transform);

// Any surface placed anew: `to_world` takes its own space (its group's, for
// a sphere or plane; the one its transform starts from, for the others) to
// the world, and its own transform (triangle, mesh, instance) follows.
void place_surface(Scene& scene, const NamedSurface& surface, const glm::dmat4& to_world);

// Every surface inside a group placed by the groups' transforms as they
// stand (a movie's frame moved some).
void place_groups(Scene& scene);

// Switches on the named lights and off all others (a movie's `lights:` list).
// Lights that are off stay in the scene, so a render that does not prune
// effects (RenderSettings::prune) can still simulate them, at zero weight.
void keep_only_lights(Scene& scene, const std::vector<std::string>& names);

}  // namespace fh
