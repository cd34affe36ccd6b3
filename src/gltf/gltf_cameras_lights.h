// glTF cameras and KHR_lights_punctual lights onto the report's cameras and
// lights (docs/gltf.md, "Cameras" and "Lights"), and what a file shown on
// its own gets when it has none. Values the specification forbids are an
// InputError naming the file.
#pragma once

#include <string>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace fh {

// Camera `index` of a file, on scene node `node`.
Camera gltf_camera(const tinygltf::Camera& camera, int index, int node, const std::string& file);

// Light `index` of a file, on scene node `node`, added to the scene's
// directional or spot lights (a point light is a spot without a cone).
// exposure: multiplies its intensity (1: the documented units).
void add_gltf_light(const tinygltf::Light& light, int index, int node, double exposure, Scene& scene,
                    const std::string& file);

// A perspective camera framing the scene's bounds from the front, above.
void add_default_camera(Scene& scene);
// Always an ambient light of 1.5 (0.15 of a colour, with the materials'
// ambient strength of 0.1); with key_light, a key light from behind
// the camera's upper left. exposure: as add_gltf_light's.
void add_default_lights(Scene& scene, const Camera& camera, double exposure, bool key_light);

}  // namespace fh
