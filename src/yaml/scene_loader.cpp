#include "yaml/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "yaml/map_reader.h"
#include "yaml/surface_reader.h"

namespace fh {

namespace {

using Keys = std::vector<std::string>;

constexpr double kTwoPi = 6.283185307179586;

// An optional block: absent or empty (null) gives a null node.
YAML::Node block(const MapReader& map, const std::string& key) {
    const MapReader::Entry* e = map.find(key);
    return e ? e->value : YAML::Node();
}

Material<double> read_material(const YamlReader& r, const YAML::Node& node, const std::string& name) {
    const MapReader m(r, node, "material '" + name + "'",
                      {"color", "ambient_color", "diffuse_color", "specular_color", "ambient", "diffuse",
                       "specular", "phong_exponent", "glazed", "reflectivity"});
    // `color` is shared by the three terms; a per-term colour overrides it, and
    // only when all three are given may `color` be left out.
    const bool all_terms = m.has("ambient_color") && m.has("diffuse_color") && m.has("specular_color");
    const dvec3 base = (all_terms && !m.has("color")) ? dvec3(0) : m.color("color");
    Material<double> mat;
    mat.ambient_color = m.has("ambient_color") ? m.color("ambient_color") : base;
    mat.diffuse_color = m.has("diffuse_color") ? m.color("diffuse_color") : base;
    mat.specular_color = m.has("specular_color") ? m.color("specular_color") : base;
    mat.ambient = m.number_up_to("ambient", 0, Limits::max_strength);
    mat.diffuse = m.number_up_to("diffuse", 0, Limits::max_strength);
    mat.specular = m.number_up_to("specular", 0, Limits::max_strength);
    mat.phong_exponent = m.number_at_least("phong_exponent", 0);
    mat.glazed = m.boolean_or("glazed", false);
    mat.reflectivity = m.has("reflectivity") ? m.number_at_least("reflectivity", 0) : 0;
    return mat;
}

void read_materials(const YamlReader& r, const YAML::Node& node, Scene& scene) {
    if (node.IsNull()) return;
    const MapReader names(r, node, "'materials'", {});
    for (const MapReader::Entry& e : names.entries()) {
        scene.material_names.push_back(e.key);
        scene.materials.push_back(read_material(r, e.value, e.key));
    }
}

void read_light(const YamlReader& r, const MapReader::Entry& entry, Scene& scene) {
    const MapReader any(r, entry.value, "light '" + entry.key + "'", {});
    const int type = r.choice(any.value("type"), "light type", {"ambient", "directional", "spot"});
    if (type == 0) {
        const MapReader m(r, entry.value, "ambient light '" + entry.key + "'", {"type", "color", "intensity"});
        if (!scene.ambient_lights.empty())
            r.fail(entry.key_node, "second ambient light '" + entry.key + "' (at most one is allowed)");
        scene.ambient_lights.push_back({entry.key, m.color("color"), m.number_up_to("intensity", 0, Limits::max_strength)});
    } else if (type == 1) {
        const MapReader m(r, entry.value, "directional light '" + entry.key + "'",
                          {"type", "color", "intensity", "direction"});
        scene.directional_lights.push_back(
            {entry.key, m.color("color"), m.number_up_to("intensity", 0, Limits::max_strength), unit_or_zero(m.direction("direction"))});
    } else {
        const MapReader m(r, entry.value, "spot light '" + entry.key + "'",
                          {"type", "color", "intensity", "position", "direction", "max_angle"});
        SpotLight<double> spot;
        spot.name = entry.key;
        spot.color = m.color("color");
        spot.intensity = m.number_up_to("intensity", 0, Limits::max_strength);
        spot.position = m.vec3("position");
        spot.axis = unit_or_zero(m.direction("direction"));
        spot.max_angle = m.has("max_angle") ? m.positive("max_angle") : kTwoPi;
        scene.spot_lights.push_back(spot);
    }
}

void read_lights(const YamlReader& r, const YAML::Node& node, Scene& scene) {
    if (node.IsNull()) return;
    const MapReader names(r, node, "'lights'", {});
    for (const MapReader::Entry& e : names.entries()) read_light(r, e, scene);
}

Camera read_camera(const YamlReader& r, const MapReader::Entry& entry) {
    const MapReader any(r, entry.value, "camera '" + entry.key + "'", {});
    const int type = r.choice(any.value("type"), "camera type", {"perspective", "orthographic"});
    const bool perspective = type == 0;
    Keys keys = {"type", "width", "height", "view_point", "look_at", "up"};
    if (perspective) keys.push_back("projection_distance");
    const MapReader m(r, entry.value, std::string(perspective ? "perspective" : "orthographic") +
                                          " camera '" + entry.key + "'", keys);
    Camera cam;
    cam.name = entry.key;
    cam.projection = perspective ? Projection::perspective : Projection::orthographic;
    cam.width = m.integer("width", 1, Limits::max_image_side);
    cam.height = m.integer("height", 1, Limits::max_image_side);
    cam.view_point = m.vec3("view_point");
    cam.look_at = m.direction("look_at");
    cam.up = m.direction("up");
    if (perspective) cam.projection_distance = m.positive("projection_distance");
    return cam;
}

void read_cameras(const YamlReader& r, const MapReader& top, Scene& scene) {
    // The cameras of the glTF files it places may be all a scene has.
    if (!top.has("cameras") && !scene.cameras.empty()) return;
    const YAML::Node node = top.value("cameras");
    const MapReader names(r, node, "'cameras'", {});
    if (names.entries().empty()) r.fail(node, "'cameras' must name at least one camera");
    for (const MapReader::Entry& e : names.entries()) scene.cameras.push_back(read_camera(r, e));
}

}  // namespace

void read_render_settings(const YamlReader& r, const YAML::Node& node, RenderSettings& settings) {
    if (node.IsNull()) return;
    const MapReader m(r, node, "'render'", {"samples_per_pixel", "max_depth", "precision"});
    if (m.has("samples_per_pixel"))
        settings.samples_per_pixel = m.integer("samples_per_pixel", 1, Limits::max_samples_per_pixel);
    if (m.has("max_depth")) settings.max_depth = m.integer("max_depth", 0, Limits::max_depth);
    if (m.has("precision"))
        settings.precision = r.choice(m.value("precision"), "precision", {"float", "double"}) == 0
                                 ? Precision::float32
                                 : Precision::float64;
}

Effects read_effects(const YamlReader& r, const YAML::Node& node) {
    r.expect_list(node, "'effects'");
    Effects fx{false, false, false, false, false};
    bool* flags[] = {&fx.ambient, &fx.diffuse, &fx.specular, &fx.shadows, &fx.glazing};
    for (const YAML::Node& name : node)
        *flags[r.choice(name, "effect", {"ambient", "diffuse", "specular", "shadows", "glazing"})] = true;
    return fx;
}

namespace {

std::string short_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

// Values that are legal but almost surely a mistake of units.
std::vector<std::string> unit_warnings(const Scene& scene, const std::string& file) {
    std::vector<std::string> out;
    const std::string at = file + ": warning: ";
    double brightest = 0;
    size_t colours = 0;
    auto see = [&](const dvec3& c) {
        brightest = std::max(brightest, max_abs_component(c));
        ++colours;
    };
    for (const auto& m : scene.materials) {
        see(m.ambient_color);
        see(m.diffuse_color);
        see(m.specular_color);
    }
    for (const auto& l : scene.ambient_lights) see(l.color);
    for (const auto& l : scene.directional_lights) see(l.color);
    for (const auto& l : scene.spot_lights) see(l.color);
    if (colours > 0 && brightest > 0 && brightest <= 1)
        out.push_back(at + "every colour is at most 1: 0-1 colours? firsthit's colours are 0-255, so the image "
                           "comes out nearly black");
    for (const auto& l : scene.spot_lights)
        if (l.max_angle > kTwoPi && std::isfinite(l.max_angle))  // infinite: a point light (glTF)
            out.push_back(at + "spot light '" + l.name + "': max_angle " + short_number(l.max_angle) +
                          " is over 2 pi: degrees? max_angle is in radians");
    for (const Camera& c : scene.cameras) {
        if (c.projection != Projection::perspective) continue;
        const double fov = 2 * std::atan(10 / c.projection_distance) * 180 / 3.14159265358979323846;
        if (fov < 1 || fov > 170)
            out.push_back(at + "camera '" + c.name + "': projection_distance " + short_number(c.projection_distance) +
                          " gives a field of view of " + short_number(fov) + " degrees (10 gives 90)");
    }
    return out;
}

// The scene in `text` (read from the file when it is null).
SceneFile load_scene_text(const std::string* text, const std::string& path) {
    try {
        const YamlReader r(path);
        const MapReader top(r, text ? r.parse_map(*text, "scene") : r.load_map("scene"), "scene",
                            {"materials", "meshes", "surfaces", "lights", "cameras", "render", "effects"});
        SceneFile file;
        Scene& scene = file.scene;
        // Materials first, whatever the file's order: surfaces refer to them.
        read_materials(r, block(top, "materials"), scene);
        std::vector<std::string> gltf_warnings;
        read_meshes_and_surfaces(r, block(top, "meshes"), block(top, "surfaces"), scene, file.animations, gltf_warnings);
        if (!scene.vertex_normals.empty()) scene.vertex_normals.resize(scene.triangles.size());
        read_lights(r, block(top, "lights"), scene);
        // The file's own cameras first (the first listed is the default),
        // then those of the glTF files it places.
        const auto gltf_cameras = std::ptrdiff_t(scene.cameras.size());
        read_cameras(r, top, scene);
        std::rotate(scene.cameras.begin(), scene.cameras.begin() + gltf_cameras, scene.cameras.end());
        read_render_settings(r, block(top, "render"), file.settings);
        if (top.has("effects")) file.settings.effects = read_effects(r, top.value("effects"));
        file.warnings = unit_warnings(scene, path);
        file.warnings.insert(file.warnings.end(), gltf_warnings.begin(), gltf_warnings.end());
        return file;
    } catch (const YAML::Exception& e) {
        throw to_input_error(path, e);
    }
}

}  // namespace

SceneFile load_scene(const std::string& path) { return load_scene_text(nullptr, path); }

SceneFile load_scene_from_string(const std::string& text, const std::string& file) {
    return load_scene_text(&text, file);
}

}  // namespace fh
