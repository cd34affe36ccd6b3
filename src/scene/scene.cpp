#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

namespace fh {

namespace {
template <typename Light>
void keep(std::vector<Light>& lights, const std::vector<std::string>& names) {
    for (Light& l : lights) l.on = std::find(names.begin(), names.end(), l.name) != names.end();
}
}  // namespace

void keep_only_lights(Scene& scene, const std::vector<std::string>& names) {
    keep(scene.ambient_lights, names);
    keep(scene.directional_lights, names);
    keep(scene.spot_lights, names);
}

void place_surface(Scene& scene, const NamedSurface& surface, const Transform& transform) {
    const PlacedMesh placed = place(*surface.mesh, transform);
    std::copy(placed.triangles.begin(), placed.triangles.end(), scene.triangles.begin() + std::ptrdiff_t(surface.index));
    if (placed.vertex_normals.empty()) return;
    std::copy(placed.vertex_normals.begin(), placed.vertex_normals.end(),
              scene.vertex_normals.begin() + std::ptrdiff_t(surface.index));
}

void place_surface(Scene& scene, const NamedSurface& surface, const glm::dmat4& to_world) {
    switch (surface.kind) {
    case SurfaceKind::sphere: {
        Sphere<double>& s = scene.spheres()[surface.index];
        s = surface.local_sphere;
        s.center = dvec3(to_world * glm::dvec4(s.center, 1.0));
        // A group scales a sphere evenly (the loader refuses other scales).
        s.radius *= std::cbrt(std::abs(glm::determinant(glm::dmat3(to_world))));
        break;
    }
    case SurfaceKind::plane: {
        Plane<double>& p = scene.planes[surface.index];
        p = surface.local_plane;
        const dvec3 point = dvec3(to_world * glm::dvec4(p.distance * p.normal, 1.0));
        p.normal = unit_or_zero(glm::inverseTranspose(glm::dmat3(to_world)) * p.normal);
        p.distance = glm::dot(p.normal, point);
        break;
    }
    case SurfaceKind::triangle:
    case SurfaceKind::mesh: {
        const PlacedMesh placed = place(*surface.mesh, to_world * surface.transform.matrix());
        std::copy(placed.triangles.begin(), placed.triangles.end(),
                  scene.triangles.begin() + std::ptrdiff_t(surface.index));
        if (!placed.vertex_normals.empty())
            std::copy(placed.vertex_normals.begin(), placed.vertex_normals.end(),
                      scene.vertex_normals.begin() + std::ptrdiff_t(surface.index));
        break;
    }
    // A movie's frame may compose a transform the loader would refuse (a
    // group scaled by 1e7 around an instance by 1e7): not drawn there.
    case SurfaceKind::instance:
        scene.instances[surface.index].to_world = usable_or_nothing(to_world * surface.transform.matrix());
        break;
    case SurfaceKind::instances: {
        const glm::dmat4 set = to_world * surface.transform.matrix();
        for (size_t k = 0; k < surface.count; ++k)
            scene.instances[surface.index + k].to_world = usable_or_nothing(set * (*surface.local_placements)[k]);
        break;
    }
    case SurfaceKind::group: break;  // its members are placed on their own
    }
}

void place_groups(Scene& scene) {
    const std::vector<glm::dmat4> world = group_matrices(scene.groups);
    for (const NamedSurface& s : scene.named_surfaces)
        if (s.group >= 0) place_surface(scene, s, world[size_t(s.group)]);
    place_nodes(scene);  // a glTF file's nodes hang under the group it is placed in
}

}  // namespace fh
