#include "io/movie_loader.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <unordered_set>

#include "io/scene_loader.h"
#include "io/map_reader.h"

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
    const fs::path path = fs::path(r.file()).parent_path() / r.string(node, "scene");
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) r.fail(node, "scene file '" + path.string() + "' does not exist");
    if (fs::is_directory(status)) r.fail(node, "scene file '" + path.string() + "' is a directory");
    if (!fs::is_regular_file(status)) r.fail(node, "scene file '" + path.string() + "' is not a regular file");
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
    fail_undefined(r, node, "camera", name, known);
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

// A value of the property: look_at and up are directions and must not be zero.
dvec3 property_value(const YamlReader& r, const YAML::Node& node, const std::string& property) {
    return property == "view_point" ? r.vec3(node, property) : r.direction(node, property);
}

Orbit read_orbit(const YamlReader& r, const YAML::Node& node) {
    const MapReader m(r, node, "'orbit'", {"center", "sin", "cos", "turns"});
    return {m.vec3("center"), m.vec3("sin"), m.vec3("cos"), m.number_or("turns", 1)};
}

Keyframes read_keyframes(const YamlReader& r, const MapReader& m, const std::string& property) {
    const YAML::Node list = m.value("keyframes");
    r.expect_list(list, "'keyframes'");
    if (list.size() == 0) r.fail(list, "'keyframes' must have at least one key");
    Keyframes k;
    std::unordered_set<int> frames;  // linear time for many keys
    for (const YAML::Node& item : list) {
        const MapReader key(r, item, "keyframe", {"frame", "value"});
        const Keyframe kf{key.integer("frame", 0, INT_MAX), property_value(r, key.value("value"), property)};
        if (!frames.insert(kf.frame).second)
            r.fail(key.value("frame"), "duplicate keyframe for frame " + std::to_string(kf.frame));
        k.keys.push_back(kf);
    }
    std::sort(k.keys.begin(), k.keys.end(), [](const Keyframe& a, const Keyframe& b) { return a.frame < b.frame; });
    if (m.has("interpolation")) {
        const int i = r.choice(m.value("interpolation"), "interpolation", {"linear", "catmull_rom"});
        k.interpolation = i == 0 ? Interpolation::linear : Interpolation::catmull_rom;
    }
    return k;
}

// One animated property: a plain [x, y, z], or a map with exactly one of
// value, orbit, toward (look_at only) or keyframes (with its interpolation).
Path read_path(const YamlReader& r, const MapReader::Entry& entry) {
    const std::string& property = entry.key;
    if (entry.value.IsSequence()) return property_value(r, entry.value, property);
    if (entry.value.IsNull()) r.fail(entry.key_node, "missing value for '" + property + "'");
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
    if (kind->key == "value") return property_value(r, m.value("value"), property);
    if (kind->key == "orbit") return read_orbit(r, m.value("orbit"));
    if (kind->key == "keyframes") return read_keyframes(r, m, property);
    // Toward aims from the view point: meaningless for the view point itself or up.
    if (property != "look_at") r.fail(kind->key_node, "'toward' is only allowed for 'look_at'");
    return Toward{m.vec3("toward")};
}

void read_animate(const YamlReader& r, const YAML::Node& node, Movie& movie) {
    if (node.IsNull()) return;
    const MapReader m(r, node, "'animate'", {"view_point", "look_at", "up"});
    for (const MapReader::Entry& e : m.entries()) {
        Path path = read_path(r, e);
        if (e.key == "view_point") movie.view_point = std::move(path);
        else if (e.key == "look_at") movie.look_at = std::move(path);
        else movie.up = std::move(path);
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
                          {"scene", "camera", "lights", "fps", "seconds", "animate", "render", "effects"});
        Movie movie;
        SceneFile scene_file = load_scene(scene_path(r, m));
        movie.scene = std::move(scene_file.scene);
        movie.settings = scene_file.settings;
        movie.camera = pick_camera(r, m, movie.scene);
        if (m.has("lights")) keep_only_lights(movie.scene, read_light_list(r, m.value("lights"), movie.scene));
        if (m.has("fps")) movie.fps = m.positive("fps");
        if (m.has("seconds")) movie.seconds = m.positive("seconds");
        check_frame_count(r, m, movie);
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
