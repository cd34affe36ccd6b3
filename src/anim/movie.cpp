#include "anim/movie.h"

#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

namespace fh {

namespace {

bool is_light(Property p) { return p >= Property::light_on && p <= Property::light_max_angle; }

// The same property of the same thing (index means nothing for the camera,
// light only for lights).
bool same_thing(const Target& a, const Target& b) {
    if (a.property != b.property) return false;
    if (is_camera(a.property)) return true;
    return a.index == b.index && (!is_light(a.property) || a.light == b.light);
}

const Animation* find(const Movie& movie, const Target& target) {
    for (const Animation& a : movie.animations)
        if (same_thing(a.target, target)) return &a;
    return nullptr;
}

Target target(Property property, size_t index = 0, LightKind light = LightKind::spot) {
    Target t;
    t.property = property;
    t.index = index;
    t.light = light;
    return t;
}

// A named triangle's or mesh's transform at a frame: the file's, with the
// animated parts replaced.
Transform transform_at(const Movie& movie, size_t surface, int frame) {
    Transform tr = movie.scene.named_surfaces[surface].transform;
    auto part = [&](Property p) -> std::optional<dvec3> {
        const Target t = target(p, surface);
        if (!find(movie, t)) return std::nullopt;
        return value_at(movie, t, frame);
    };
    if (auto v = part(Property::transform_translate)) tr.translate = *v;
    if (auto v = part(Property::transform_scale)) tr.scale = *v;
    if (auto v = part(Property::transform_axis)) tr.axis = *v;
    if (auto v = part(Property::transform_degrees)) tr.radians = v->x * std::numbers::pi / 180;
    if (auto v = part(Property::transform_radians)) tr.radians = v->x;
    return tr;
}

// The world matrix of group g at a frame: its parents' and its own
// transforms, animated parts replaced.
glm::dmat4 group_world_at(const Movie& movie, int g, int frame) {
    glm::dmat4 world(1.0);
    for (; g >= 0; g = movie.scene.groups[size_t(g)].parent) {
        size_t named = 0;  // the group's record, which animations address
        while (movie.scene.named_surfaces[named].kind != SurfaceKind::group ||
               movie.scene.named_surfaces[named].index != size_t(g))
            ++named;
        world = transform_at(movie, named, frame).matrix() * world;
    }
    return world;
}

// Where a followed thing is at a frame: a spot light's position, a sphere's
// centre, a triangle's, mesh's or instance's own centre (of its bounding box
// as read) carried by its transform, a group's origin -- each carried by the
// groups around it.
dvec3 followed(const Movie& movie, const Follow& f, int frame) {
    if (f.spot_light) return value_at(movie, target(Property::light_position, f.index), frame);
    const NamedSurface& s = movie.scene.named_surfaces[f.index];
    const bool grouped = s.group >= 0;
    const glm::dmat4 around = grouped ? group_world_at(movie, s.group, frame) : glm::dmat4(1.0);
    if (s.kind == SurfaceKind::sphere) {
        const dvec3 c = value_at(movie, target(Property::sphere_center, f.index), frame);
        return grouped ? dvec3(around * glm::dvec4(c, 1.0)) : c;
    }
    if (s.kind == SurfaceKind::group) return dvec3(group_world_at(movie, int(s.index), frame)[3]);
    const Mesh& mesh = s.kind == SurfaceKind::instance
        ? *movie.scene.meshes[size_t(movie.scene.instances[s.index].mesh)].mesh : *s.mesh;
    dvec3 lo(kInfinity<double>), hi(-kInfinity<double>);
    for (const dvec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Transform tr = transform_at(movie, f.index, frame);
    if (!grouped && tr.identity()) return 0.5 * (lo + hi);
    return dvec3(around * tr.matrix() * glm::dvec4(0.5 * (lo + hi), 1.0));
}

// Where a Toward aims from: the camera's eye, a spot light's position.
dvec3 origin_of(const Movie& movie, const Target& t, int frame) {
    if (t.property == Property::camera_look_at) return value_at(movie, target(Property::camera_view_point), frame);
    return value_at(movie, target(Property::light_position, t.index), frame);
}

std::string shown(const Target& t, const dvec3& v) {
    std::ostringstream out;
    out.precision(6);
    switch (t.kind) {
    case ValueKind::point: case ValueKind::direction: case ValueKind::color: case ValueKind::scale:
        out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
        break;
    case ValueKind::flag: out << (v.x != 0 ? "true" : "false"); break;
    default: out << v.x;
    }
    return out.str();
}

}  // namespace

int Movie::frame_count() const {
    return static_cast<int>(std::llround(fps * seconds));
}

void Movie::animate_camera(Property property, Path path) {
    Target t = target(property);
    for (const PropertyName& p : camera_properties(Projection::perspective))
        if (p.property == property) {
            t.kind = p.kind;
            t.path = std::string("camera.") + p.name;
        }
    for (Animation& a : animations)
        if (same_thing(a.target, t)) {
            a.path = std::move(path);
            return;
        }
    animations.push_back({t, std::move(path)});
}

bool Movie::scene_changes() const {
    if (!node_channels.empty()) return true;
    for (const Animation& a : animations)
        if (!is_camera(a.target.property)) return true;
    return false;
}

ShapeChanges Movie::shape_changes() const {
    ShapeChanges changes;
    changes.instances = !node_channels.empty();  // glTF nodes carry instances
    // What a surface moves; a group moves what it holds, at any depth.
    auto mark = [&](const NamedSurface& s) {
        const bool placed = s.kind == SurfaceKind::instance || s.kind == SurfaceKind::instances;
        if (s.kind != SurfaceKind::group) (placed ? changes.instances : changes.world) = true;
    };
    for (const Animation& a : animations) {
        if (!moves_shapes(a.target.property)) continue;
        const NamedSurface& s = scene.named_surfaces[a.target.index];
        if (s.kind != SurfaceKind::group) {
            mark(s);
            continue;
        }
        for (const NamedSurface& member : scene.named_surfaces)
            if (group_holds(scene.groups, s.index, member.group)) mark(member);
    }
    return changes;
}

dvec3 value_at(const Movie& movie, const Target& t, int frame) {
    const Animation* a = find(movie, t);
    if (!a) return value_of(t, movie.scene, movie.camera);
    const int n = movie.frame_count();
    if (const auto* toward = std::get_if<Toward>(&a->path)) {
        const dvec3 to = toward->follow ? followed(movie, *toward->follow, frame) : evaluate(toward->point, frame, n);
        return aim(origin_of(movie, t, frame), to);
    }
    return evaluate(a->path, frame, n, dvec3(0));
}

Camera camera_at(const Movie& movie, int frame) {
    Camera cam = movie.camera;
    if (cam.node >= 0 && !movie.node_channels.empty()) {
        // A glTF camera on an animated node: the nodes at this frame place it.
        Scene nodes;
        nodes.groups = movie.scene.groups;
        nodes.nodes = movie.scene.nodes;
        nodes.cameras = {cam};
        apply_channels(movie.node_channels, frame / movie.fps, nodes);
        place_nodes(nodes);
        cam = nodes.cameras[0];
    }
    Scene none;  // set_value's scene: camera properties never touch it
    for (const Animation& a : movie.animations)
        if (is_camera(a.target.property)) set_value(a.target, value_at(movie, a.target, frame), none, cam);
    return cam;
}

void scene_at(const Movie& movie, int frame, Scene& scene) {
    Camera unused;
    std::set<size_t> placed;  // surfaces whose transform moves
    bool groups_move = false;  // something in a group, or a group, moves
    for (const Animation& a : movie.animations) {
        if (is_camera(a.target.property)) continue;
        const bool surface = moves_shapes(a.target.property);
        if (surface && scene.named_surfaces[a.target.index].group >= 0) groups_move = true;
        if (is_transform(a.target.property)) placed.insert(a.target.index);
        else set_value(a.target, value_at(movie, a.target, frame), scene, unused);
    }
    for (const size_t s : placed) {
        NamedSurface& named = scene.named_surfaces[s];
        named.transform = transform_at(movie, s, frame);
        if (named.kind == SurfaceKind::group) {
            scene.groups[named.index].transform = named.transform;
            groups_move = true;
        } else if (named.group < 0) {
            if (named.kind == SurfaceKind::triangle || named.kind == SurfaceKind::mesh)
                place_surface(scene, named, named.transform);
            else
                place_surface(scene, named, glm::dmat4(1.0));
        }
    }
    if (!movie.node_channels.empty()) {
        apply_channels(movie.node_channels, frame / movie.fps, scene);
        if (!groups_move) place_nodes(scene);  // (place_groups places the nodes too)
    }
    if (groups_move) place_groups(scene);
    // Morphs and skins follow their nodes (a group's move leaves them as they are).
    if (!movie.node_channels.empty()) deform_meshes(scene);
}

std::vector<int> check_animations(const Movie& movie) {
    std::vector<int> parallel;
    const int n = movie.frame_count();
    for (int i = 0; i < n; ++i) {
        for (const Animation& a : movie.animations) {
            const dvec3 v = value_at(movie, a.target, i);
            const std::string why = check_value(a.target, v);
            if (!why.empty())
                throw AnimationError(a.target.path + " is " + shown(a.target, v) + " at frame " +
                                         std::to_string(i) + "; " + why, a.line, a.column);
        }
        const Camera cam = camera_at(movie, i);
        // Checked before camera_basis, which would turn these into NaN.
        if (!is_finite(cam.look_at))
            throw AnimationError("view direction is not finite at frame " + std::to_string(i), 0, 0);
        if (max_abs_component(cam.look_at) == 0)
            throw AnimationError("view direction is zero-length at frame " + std::to_string(i), 0, 0);
        if (camera_basis(cam.look_at, cam.up).up_was_parallel) parallel.push_back(i);
    }
    return parallel;
}

}  // namespace fh
