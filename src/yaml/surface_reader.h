// A scene file's `meshes:` and `surfaces:` (docs/format.md): every surface
// type, placed in the world -- spheres, planes, triangles and `type: mesh`
// as world-space primitives, `instance` and `instances` as placements of a
// mesh loaded once, `group` as a transform over what it holds. Strict like
// the rest of the scene file: every mistake is an InputError at its key.
#pragma once

#include <yaml-cpp/yaml.h>

#include "anim/node_channel.h"
#include "scene/scene.h"
#include "yaml/yaml_reader.h"

namespace fh {

class MapReader;

// The `meshes:` map (each mesh in its own space), then the `surfaces:` list,
// after the materials: a file is read once, however many entries of either
// name it. The glTF files the surfaces place add their animations and
// warnings to these.
void read_meshes_and_surfaces(const YamlReader& reader, const YAML::Node& meshes, const YAML::Node& surfaces,
                              Scene& scene, std::vector<NodeAnimation>& animations, std::vector<std::string>& warnings);

// A `transform:` map (scene/mesh.h): scale, then rotate, then translate.
Transform read_transform(const YamlReader& reader, const YAML::Node& node);

// The index of the material a surface's `material:` names.
int material_index(const MapReader& map, const Scene& scene);

}  // namespace fh
