// The scene as a file describes it (report sections 3-7): surfaces, materials,
// lights and cameras, in double precision. How to render it (quality, effects)
// travels beside it in RenderSettings (render/settings.h). The tracer builds
// its own flat copy in its scalar type (render/flat_scene.h).
#pragma once

#include <string>
#include <vector>

#include "geometry/plane.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "scene/camera.h"
#include "scene/lights.h"
#include "scene/material.h"
#include "scene/spot_light.h"

namespace fh {

struct Scene {
    std::vector<std::string> material_names;  // parallel to materials
    std::vector<Material<double>> materials;
    std::vector<Sphere<double>> spheres;
    std::vector<Plane<double>> planes;
    std::vector<Triangle<double>> triangles;
    std::vector<AmbientLight<double>> ambient_lights;  // at most one
    std::vector<DirectionalLight<double>> directional_lights;
    std::vector<SpotLight<double>> spot_lights;
    std::vector<Camera> cameras;
    int meshes = 0;                        // mesh files read into `triangles`
    size_t degenerate_mesh_triangles = 0;  // their zero-area triangles, left out

    const Camera* find_camera(const std::string& name) const {
        for (const Camera& c : cameras)
            if (c.name == name) return &c;
        return nullptr;
    }
};

// Switches on the named lights and off all others (a movie's `lights:` list).
// Lights that are off stay in the scene, so a render that does not prune
// effects (RenderSettings::prune) can still simulate them, at zero weight.
void keep_only_lights(Scene& scene, const std::vector<std::string>& names);

}  // namespace fh
