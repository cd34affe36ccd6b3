#include "yaml/movie_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unordered_set>

#include "files/input_files.h"
#include "gltf/gltf_loader.h"
#include "gltf/gltf_movie.h"
#include "yaml/key_list.h"
#include "yaml/node_paths.h"
#include "yaml/scene_loader.h"
#include "yaml/map_reader.h"

namespace fh {

namespace {

namespace fs = std::filesystem;

// "undefined camera 'x'", with a hint when a known name is close.
[[noreturn]] void fail_undefined(const YamlReader& r, const YAML::Node& node, const std::string& kind,
                                 const std::string& name, const std::vector<std::string>& known) {
    const std::string hint = closest_match(name, known);
    r.fail(node, "undefined " + kind + " '" + name + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

std::string scene_path(const YamlReader& r, const MapReader& m) {
    const YAML::Node node = m.value("scene");
    const fs::path path = fs::path(r.file()).parent_path() / r.file_name(node, "scene");
    if (const std::string why = why_unreadable(path.string()); !why.empty())
        r.fail(node, "scene file '" + path.string() + "': " + why);
    std::error_code ec;
    if (fs::equivalent(path, r.file(), ec)) r.fail(node, "a movie cannot be its own scene");
    // Loading a movie as a scene would only complain about an unknown key 'scene'.
    if (is_movie_file(path.string())) r.fail(node, "scene file '" + path.string() + "' is a movie, not a scene");
    return path.string();
}

Camera pick_camera(const YamlReader& r, const MapReader& m, const Scene& scene) {
    if (!m.has("camera")) return scene.cameras.front();
    const YAML::Node node = m.value("camera");
    const std::string name = r.string(node, "camera");
    if (const Camera* cam = scene.find_camera(name)) return *cam;
    std::vector<std::string> known;
    for (const Camera& c : scene.cameras) known.push_back(c.name);
    r.fail(node, "undefined camera '" + name + "'" + name_hint(name, known, "the scene's cameras"));
}

std::vector<std::string> light_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& l : scene.ambient_lights) names.push_back(l.name);
    for (const auto& l : scene.directional_lights) names.push_back(l.name);
    for (const auto& l : scene.spot_lights) names.push_back(l.name);
    return names;
}

std::vector<std::string> read_light_list(const YamlReader& r, const YAML::Node& node, const Scene& scene) {
    r.expect_list(node, "'lights'");
    const std::vector<std::string> known = light_names(scene);
    std::vector<std::string> names;
    for (const YAML::Node& item : node) {
        const std::string name = r.string(item, "lights");
        if (std::find(known.begin(), known.end(), name) == known.end())
            fail_undefined(r, item, "light", name, known);
        names.push_back(name);
    }
    return names;
}

// fps * seconds rounded, checked here in double so a huge product cannot
// overflow Movie::frame_count()'s int.
void check_frame_count(const YamlReader& r, const MapReader& m, const Movie& movie) {
    const double frames = std::round(movie.fps * movie.seconds);
    if (frames >= 1 && frames <= kMaxMovieFrames) return;
    const YAML::Node at = m.has("seconds") ? m.value("seconds") : m.has("fps") ? m.value("fps") : m.node();
    if (frames < 1) r.fail(at, "fps * seconds gives no frames");
    r.fail(at, "fps * seconds gives more than " + std::to_string(kMaxMovieFrames) + " frames");
}

std::string join(const std::vector<std::string>& words, size_t from, const char* sep = ".") {
    std::string out;
    for (size_t i = from; i < words.size(); ++i) out += (i > from ? sep : "") + words[i];
    return out;
}

std::vector<std::string> split(const std::string& path) {
    std::vector<std::string> words(1);
    for (const char c : path) {
        if (c == '.') words.emplace_back();
        else words.back() += c;
    }
    return words;
}

// The property `rest` of a thing (`what`: "light 'spot'"), or one line
// listing what it can animate.
Target pick_property(const YamlReader& r, const YAML::Node& at, const std::string& path, const std::string& what,
                     const std::string& rest, const std::vector<PropertyName>& properties) {
    std::vector<std::string> names;
    for (const PropertyName& p : properties) {
        if (rest == p.name) {
            Target t;
            t.property = p.property;
            t.kind = p.kind;
            t.path = path;
            return t;
        }
        names.push_back(p.name);
    }
    const std::string hint = closest_match(rest, names);
    r.fail(at, "unknown property '" + rest + "' in '" + path + "': " + what + " can animate " + join(names, 0, ", ") +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

// The animated property a path in `animate:` names (anim/property.h).
Target read_target(const YamlReader& r, const YAML::Node& at, const std::string& written, const Movie& movie) {
    // The old keys mean the camera's.
    const bool old = written == "view_point" || written == "look_at" || written == "up";
    const std::string path = old ? "camera." + written : written;
    const std::vector<std::string> words = split(path);
    const Scene& scene = movie.scene;
    if (words[0] == "camera")
        return pick_property(r, at, path, "the camera", join(words, 1), camera_properties(movie.camera.projection));
    const std::vector<std::string> kinds = {"camera", "lights", "surfaces", "materials", "nodes"};
    if (std::find(kinds.begin(), kinds.end(), words[0]) == kinds.end() || words.size() < 3) {
        const std::string hint = closest_match(words[0], kinds);
        r.fail(at, "unknown property path '" + written + "': a path is camera.PROPERTY, lights.NAME.PROPERTY, "
                   "surfaces.NAME.PROPERTY, materials.NAME.PROPERTY or nodes.NAME.PROPERTY" +
                   (hint.empty() || hint == words[0] ? "" : " (did you mean '" + hint + "'?)"));
    }
    const std::string& name = words[1];
    const std::string rest = join(words, 2);
    if (words[0] == "lights") {
        auto in = [&](const auto& lights, LightKind kind, const char* what) -> std::optional<Target> {
            for (size_t i = 0; i < lights.size(); ++i) {
                if (lights[i].name != name) continue;
                Target t = pick_property(r, at, path, std::string(what) + " '" + name + "'", rest, light_properties(kind));
                t.light = kind;
                t.index = i;
                return t;
            }
            return std::nullopt;
        };
        if (auto t = in(scene.ambient_lights, LightKind::ambient, "ambient light")) return *t;
        if (auto t = in(scene.directional_lights, LightKind::directional, "directional light")) return *t;
        if (auto t = in(scene.spot_lights, LightKind::spot, "spot light")) return *t;
        fail_undefined(r, at, "light", name, light_names(scene));
    }
    if (words[0] == "materials") {
        const auto& names = scene.material_names;
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end()) fail_undefined(r, at, "material", name, names);
        Target t = pick_property(r, at, path, "material '" + name + "'", rest, material_properties());
        t.index = size_t(it - names.begin());
        return t;
    }
    std::vector<std::string> names;
    for (size_t i = 0; i < scene.named_surfaces.size(); ++i) {
        const NamedSurface& s = scene.named_surfaces[i];
        if (s.name.empty()) continue;  // a group's unnamed member
        names.push_back(s.name);
        if (s.name != name) continue;
        const char* kind[] = {"sphere", "plane", "triangle", "mesh", "instance", "instances", "group"};
        const std::string what = s.colored_mesh ? "mesh" : kind[int(s.kind)];
        Target t = pick_property(r, at, path, what + " '" + name + "'", rest,
                                 surface_properties(s.kind));
        t.index = i;
        return t;
    }
    const std::string hint = closest_match(name, names);
    r.fail(at, "no surface named '" + name + "' (a surface gets one with 'name:' in the scene)" +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

// One value of the target's kind.
dvec3 read_value(const YamlReader& r, const YAML::Node& node, const Target& t) {
    switch (t.kind) {
    case ValueKind::point: return r.vec3(node, t.path);
    case ValueKind::direction: return r.direction(node, t.path);
    case ValueKind::color: return r.color(node, t.path);
    case ValueKind::scale: return node.IsSequence() ? r.vec3(node, t.path) : dvec3(r.number(node, t.path));
    case ValueKind::flag: return dvec3(r.boolean(node, t.path) ? 1 : 0);
    default: return dvec3(r.number(node, t.path));
    }
}

bool is_vector(const Target& t) {
    return t.kind == ValueKind::point || t.kind == ValueKind::direction || t.kind == ValueKind::color;
}

Orbit read_orbit(const YamlReader& r, const YAML::Node& node) {
    const MapReader m(r, node, "'orbit'", {"center", "sin", "cos", "turns"});
    return {m.vec3("center"), m.vec3("sin"), m.vec3("cos"), m.number_or("turns", 1)};
}

// Keys at `frame:` or `time:` (yaml/key_list.h), each value of the target's kind.
Keyframes read_keyframes(const YamlReader& r, const MapReader& m, const Target& t, const Movie& movie) {
    Keyframes k;
    for (const KeyNode& key : read_key_list(r, m.value("keyframes"), movie))
        k.keys.push_back({key.frame, read_value(r, key.value, t)});
    k.interpolation = t.kind == ValueKind::flag ? Interpolation::step : Interpolation::linear;
    if (m.has("interpolation")) {
        const std::vector<std::string> names = {"step", "linear", "catmull_rom", "ease_in", "ease_out", "ease_in_out"};
        const int i = r.choice(m.value("interpolation"), "interpolation", names);
        if (t.kind == ValueKind::flag && i != 0) r.fail(m.value("interpolation"), "'" + t.path + "' only steps: use interpolation: step");
        k.interpolation = Interpolation(i);
    }
    return k;
}

// A point that moves: fixed, an orbit or keyframes (a Toward's target).
PointPath read_point_path(const YamlReader& r, const YAML::Node& node, const std::string& where, const Movie& movie) {
    if (node.IsSequence()) return r.vec3(node, where);
    const MapReader m(r, node, "'" + where + "'", {"orbit", "keyframes", "interpolation"});
    if (m.has("orbit") == m.has("keyframes"))
        r.fail(node, "'" + where + "' takes a point, or one of 'orbit' or 'keyframes'");
    if (m.has("orbit")) return read_orbit(r, m.value("orbit"));
    Target point;
    point.kind = ValueKind::point;
    point.path = where;
    return read_keyframes(r, m, point, movie);
}

// What a Toward aims at: a point, a moving point, or a named thing.
Toward read_toward(const YamlReader& r, const YAML::Node& node, const Movie& movie) {
    if (!node.IsScalar()) return {read_point_path(r, node, "toward", movie), std::nullopt};
    const std::vector<std::string> words = split(node.Scalar());
    const Scene& scene = movie.scene;
    if (words.size() == 2 && words[0] == "lights") {
        for (size_t i = 0; i < scene.spot_lights.size(); ++i)
            if (scene.spot_lights[i].name == words[1]) return {dvec3(0), Follow{true, i, node.Scalar()}};
        for (const auto& l : scene.directional_lights)
            if (l.name == words[1]) r.fail(node, "'toward' cannot follow a directional light: it has no position");
        for (const auto& l : scene.ambient_lights)
            if (l.name == words[1]) r.fail(node, "'toward' cannot follow an ambient light: it has no position");
    }
    if (words.size() == 2 && words[0] == "surfaces") {
        if (const NamedSurface* s = scene.find_surface(words[1])) {
            if (s->kind == SurfaceKind::plane) r.fail(node, "'toward' cannot follow a plane: it has no centre");
            if (s->kind == SurfaceKind::instances)
                r.fail(node, "'toward' cannot follow a set of instances: name one instance, or their group");
            return {dvec3(0), Follow{false, size_t(s - scene.named_surfaces.data()), node.Scalar()}};
        }
    }
    r.fail(node, "'toward' follows 'surfaces.NAME' (a named sphere, triangle, mesh, instance or group) or 'lights.NAME' "
                 "(a spot light); no such thing as '" + node.Scalar() + "'");
}

// One animated property: a plain value, or a map with exactly one of value,
// orbit, toward or keyframes (with its interpolation).
Path read_path(const YamlReader& r, const MapReader::Entry& entry, const Target& t, const Movie& movie) {
    const std::string& property = entry.key;
    if (entry.value.IsNull()) r.fail(entry.key_node, "missing value for '" + property + "'");
    if (!entry.value.IsMap()) return read_value(r, entry.value, t);
    const MapReader m(r, entry.value, "'" + property + "'", {"value", "orbit", "toward", "keyframes", "interpolation"});
    const MapReader::Entry* kind = nullptr;
    for (const MapReader::Entry& e : m.entries()) {
        if (e.key == "interpolation") continue;
        if (kind) r.fail(e.key_node, "'" + property + "' takes only one of 'value', 'orbit', 'toward' or 'keyframes'");
        kind = &e;
    }
    if (!kind) r.fail(m.node(), "'" + property + "' needs one of 'value', 'orbit', 'toward' or 'keyframes'");
    if (const MapReader::Entry* interp = m.find("interpolation"); interp && kind->key != "keyframes")
        r.fail(interp->key_node, "'interpolation' only applies to 'keyframes'");
    if (kind->key == "value") return read_value(r, m.value("value"), t);
    if (kind->key == "keyframes") return read_keyframes(r, m, t, movie);
    if (kind->key == "orbit") {
        if (!is_vector(t)) r.fail(kind->key_node, "'orbit' moves a vector; '" + t.path + "' is not one");
        return read_orbit(r, m.value("orbit"));
    }
    // Toward aims from a place: the camera's eye, a spot light's position.
    const bool spot_direction = t.property == Property::light_direction && t.light == LightKind::spot;
    if (t.property != Property::camera_look_at && !spot_direction)
        r.fail(kind->key_node, "'toward' is only allowed for 'camera.look_at' and a spot light's 'direction'");
    return read_toward(r, m.value("toward"), movie);
}

// A group holding a sphere, at any depth, scales by one number (the scene
// loader refuses other scales: a sphere would be an ellipsoid). Keys of
// x = y = z keep every frame between them even too.
void check_sphere_scales(const YamlReader& r, const MapReader::Entry& e, const Animation& a, const Scene& scene) {
    if (a.target.property != Property::transform_scale) return;
    const NamedSurface& target = scene.named_surfaces[a.target.index];
    if (target.kind != SurfaceKind::group) return;
    const bool holds_sphere = std::any_of(scene.named_surfaces.begin(), scene.named_surfaces.end(), [&](const NamedSurface& s) {
        return s.kind == SurfaceKind::sphere && group_holds(scene.groups, target.index, s.group);
    });
    if (!holds_sphere) return;
    auto even = [](const dvec3& v) { return v.x == v.y && v.y == v.z; };
    const Keyframes* keys = std::get_if<Keyframes>(&a.path);
    const bool ok = keys ? std::all_of(keys->keys.begin(), keys->keys.end(), [&](const Keyframe& k) { return even(k.value); })
                         : even(std::get<dvec3>(a.path));
    if (!ok)
        r.fail(e.value, "'" + a.target.path + "' must scale by one number: group '" + target.name +
                            "' holds a sphere, which an uneven scale would make an ellipsoid");
}

void read_animate(const YamlReader& r, const YAML::Node& node, Movie& movie) {
    if (node.IsNull()) return;
    const MapReader m(r, node, "'animate'", {});
    for (const MapReader::Entry& e : m.entries()) {
        if (is_node_path(e.key)) {  // after the file's channels: it overrides them
            movie.node_channels.push_back(read_node_path(r, e, movie));
            continue;
        }
        const Target t = read_target(r, e.key_node, e.key, movie);
        for (const Animation& a : movie.animations)
            if (a.target.path == t.path)
                r.fail(e.key_node, "'" + t.path + "' is animated twice");
        auto is_angle = [](Property p) { return p == Property::transform_degrees || p == Property::transform_radians; };
        for (const Animation& a : movie.animations)
            if (is_angle(t.property) && is_angle(a.target.property) && a.target.index == t.index)
                r.fail(e.key_node, "'" + t.path + "': animate the angle in degrees or in radians, not both");
        const YAML::Mark mark = e.key_node.Mark();
        movie.animations.push_back({t, read_path(r, e, t, movie), mark.line + 1, mark.column + 1});
        check_sphere_scales(r, e, movie.animations.back(), movie.scene);
    }
}

YAML::Node block(const MapReader& m, const std::string& key) {
    const MapReader::Entry* e = m.find(key);
    return e ? e->value : YAML::Node();
}

}  // namespace

namespace {

// The movie in `text` (read from the file when it is null).
Movie load_movie_text(const std::string* text, const std::string& path) {
    try {
        const YamlReader r(path);
        const MapReader m(r, text ? r.parse_map(*text, "movie") : r.load_map("movie"), "movie",
                          {"scene", "camera", "lights", "fps", "seconds", "width", "height", "animate", "render",
                           "effects", "animation"});
        Movie movie;
        const std::string scene = scene_path(r, m);
        SceneFile scene_file;
        if (is_gltf_file(scene)) {  // a glTF file as the scene: its cameras, lights, animations
            GltfScene g = gltf_scene(scene);
            scene_file.scene = std::move(g.scene);
            scene_file.animations = std::move(g.animations);
            scene_file.warnings = std::move(g.warnings);
        } else {
            scene_file = load_scene(scene);
        }
        movie.scene = std::move(scene_file.scene);
        movie.settings = scene_file.settings;
        movie.warnings = std::move(scene_file.warnings);
        movie.camera = pick_camera(r, m, movie.scene);
        // The animations of its glTF files: all, or the one `animation:` names.
        if (m.has("animation") || !scene_file.animations.empty()) {
            const std::string which = m.has("animation") ? m.string("animation") : "all";
            try {
                movie.node_channels = chosen_channels(scene_file.animations, which, scene);
            } catch (const UsageError& e) {
                r.fail(m.value("animation"), e.what());
            }
        }
        if (m.has("lights")) keep_only_lights(movie.scene, read_light_list(r, m.value("lights"), movie.scene));
        if (m.has("fps")) movie.fps = m.positive("fps");
        if (m.has("seconds")) movie.seconds = m.positive("seconds");
        check_frame_count(r, m, movie);
        // A preview or a 4K version without a copy of the scene.
        if (m.has("width")) movie.camera.width = m.integer("width", 1, Limits::max_image_side);
        if (m.has("height")) movie.camera.height = m.integer("height", 1, Limits::max_image_side);
        read_animate(r, block(m, "animate"), movie);
        read_render_settings(r, block(m, "render"), movie.settings);
        if (m.has("effects")) movie.settings.effects = read_effects(r, m.value("effects"));
        return movie;
    } catch (const YAML::Exception& e) {
        throw to_input_error(path, e);
    }
}

}  // namespace

Movie load_movie(const std::string& path) { return load_movie_text(nullptr, path); }

Movie load_movie_from_string(const std::string& text, const std::string& path) {
    return load_movie_text(&text, path);
}

bool is_movie_file(const std::string& path) {
    // A .gltf is JSON, which reads as YAML, and its "scene" key names the
    // file's default scene: it is a scene, never a movie.
    if (is_gltf_file(path)) return false;
    try {
        // The same checked reading as loading: size, text, nesting.
        const YamlReader r(path);
        const YAML::Node root = r.load_map("movie");
        for (auto it = root.begin(); it != root.end(); ++it) {
            const YAML::Node key = it->first;
            if (key.IsScalar() && key.Scalar() == "scene") return true;
        }
        return false;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace fh
