// The scene file (docs/format.md): materials, surfaces,
// lights, cameras, and optional render settings and effects. Loading is strict:
// unknown or repeated keys, values of the wrong type or out of range, names that
// refer to nothing are all fh::InputError with the file, line and column.
#pragma once

#include <string>
#include <vector>

#include "anim/node_channel.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace YAML {
class Node;
}

namespace fh {

class YamlReader;

// A scene file: the scene it describes and the render settings it asks for
// (its `render:` and `effects:` blocks).
struct SceneFile {
    // Likely unit mistakes, one line each ("FILE: warning: ..."): the render
    // goes on (0-1 colours, max_angle in degrees, a field of view under 1
    // or over 170 degrees).
    std::vector<std::string> warnings;
    Scene scene;
    RenderSettings settings;
    // The animations of the glTF files it places (type: gltf), their
    // channels on the scene's nodes: a movie over this scene may play them.
    std::vector<NodeAnimation> animations;
};

// Loads a scene file. Unreadable file, YAML syntax error or any bad value:
// InputError. Normals and light directions come out unit length; a plane's
// distance is rescaled with its normal so it stays the same plane.

SceneFile load_scene(const std::string& path);

// The same from the file's text in memory; `file` only names it in errors
// (the fuzzer and tests use this). The text gets the checks of a file's:
// size, text encoding and nesting depth (yaml/yaml_reader.h).
SceneFile load_scene_from_string(const std::string& text, const std::string& file);

// The `render:` map (samples_per_pixel, max_depth, precision): each key given
// replaces the value in `settings`, so a movie can override a scene's. A null
// node changes nothing.
void read_render_settings(const YamlReader& reader, const YAML::Node& node, RenderSettings& settings);

// The `effects:` list: the effects named are on, all others off.
Effects read_effects(const YamlReader& reader, const YAML::Node& node);

}  // namespace fh
