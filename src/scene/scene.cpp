#include "scene/scene.h"

#include <algorithm>

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

}  // namespace fh
