#include "yaml/surface_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <unordered_set>

#include <glm/gtc/matrix_transform.hpp>

#include "gltf/gltf_loader.h"
#include "meshes/mesh_loader.h"
#include "render/settings.h"
#include "text/input_error.h"
#include "yaml/map_reader.h"
#include "yaml/placements.h"

namespace fh {

namespace {

// Where surfaces are read: the group they are in (if any) and that group's
// world matrix.
struct Place {
    int group = -1;
    glm::dmat4 world{1.0};
};

// The vertex normals stay in step with the triangles once a smooth mesh
// has some: zeros (flat) for every other triangle.
void add_triangles(Scene& scene, const PlacedMesh& placed) {
    if (!placed.vertex_normals.empty() || !scene.vertex_normals.empty()) {
        scene.vertex_normals.resize(scene.triangles.size());
        if (placed.vertex_normals.empty()) scene.vertex_normals.resize(scene.triangles.size() + placed.triangles.size());
        else scene.vertex_normals.insert(scene.vertex_normals.end(), placed.vertex_normals.begin(), placed.vertex_normals.end());
    }
    scene.triangles.insert(scene.triangles.end(), placed.triangles.begin(), placed.triangles.end());
}

// A triangle as a mesh of one, so that a movie can move it like a mesh.
Mesh read_triangle(const MapReader& m, int material) {
    const YAML::Node v = m.value("vertices");
    const YamlReader& r = m.reader();
    if (!v.IsSequence() || v.size() != 3) r.fail(v, "expected a list of 3 points for 'vertices'");
    // A zero-area triangle is accepted: it has a zero normal and never hits.
    Mesh mesh;
    mesh.positions = {r.vec3(v[0], "vertices"), r.vec3(v[1], "vertices"), r.vec3(v[2], "vertices")};
    mesh.triangles = {{0, 1, 2}};
    mesh.material = material;
    return mesh;
}

class SurfaceReader {
public:
    SurfaceReader(const YamlReader& r, Scene& scene, std::vector<NodeAnimation>* animations = nullptr,
                  std::vector<std::string>* warnings = nullptr)
        : r_(r), scene_(scene), animations_(animations), warnings_(warnings) {
        for (const NamedSurface& s : scene.named_surfaces) names_.insert(s.name);
    }

    void read_meshes(const YAML::Node& node) {
        const MapReader names(r_, node, "'meshes'", {});
        for (const MapReader::Entry& e : names.entries()) {
            const MapReader m(r_, e.value, "mesh '" + e.key + "'", {"file", "smooth"});
            scene_.degenerate_mesh_triangles += load(m).degenerate_dropped;
            scene_.meshes.push_back({e.key, scene_mesh(m)});
        }
    }

    void read_list(const YAML::Node& node, const Place& place) {
        if (node.IsNull()) return;
        r_.expect_list(node, "'surfaces'");
        for (const YAML::Node& surface : node) read(surface, place);
    }

private:
    using Keys = std::vector<std::string>;
    static constexpr const char* kTypes[] = {"sphere", "plane", "triangle", "mesh", "instance", "instances", "group",
                                             "disk", "gltf"};

    void read(const YAML::Node& node, const Place& place) {
        // The type decides which keys are allowed, so it is read first.
        const MapReader any(r_, node, "surface", {});
        const Keys types(std::begin(kTypes), std::end(kTypes));
        NamedSurface named;
        named.group = place.group;
        const int type = r_.choice(any.value("type"), "surface type", types);
        switch (type) {
        case 0: read_sphere(node, place, named); break;
        case 1: read_plane(node, place, named); break;
        case 2: case 3: read_triangles(node, place, named, type == 3); break;
        case 4: read_instance(node, place, named); break;
        case 5: read_instances(node, place, named); break;
        case 6: read_group(node, place, named); return;  // recorded before its members
        case 7: read_disk(node, place); return;
        default: read_gltf(node, place, named); return;
        }
        if (!named.name.empty() || named.group >= 0) scene_.named_surfaces.push_back(std::move(named));
    }

    void read_sphere(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "sphere", {"type", "name", "center", "radius", "material"});
        named.name = name(m);
        named.kind = SurfaceKind::sphere;
        named.index = scene_.spheres().size();
        named.local_sphere = {m.vec3("center"), m.positive_up_to("radius", Limits::max_radius),
                              material_index(m, scene_)};
        scene_.spheres().push_back(named.local_sphere);
        if (place.group < 0) return;
        const glm::dmat3 a(place.world);
        const double sx = glm::length(a[0]), sy = glm::length(a[1]), sz = glm::length(a[2]);
        if (std::abs(sx - sy) > 1e-9 * sx || std::abs(sx - sz) > 1e-9 * sx)
        {
            const std::string& group = scene_.groups[size_t(place.group)].name;
            r_.fail(node, "a sphere in a group scaled unevenly would be an ellipsoid: scale the group" +
                              (group.empty() ? std::string() : " '" + group + "'") +
                              " (and those around it) by one number");
        }
        place_surface(scene_, named, place.world);
    }

    // A disk: fixed where the file puts it (no name, not in a group: it has
    // no animatable properties yet).
    void read_disk(const YAML::Node& node, const Place& place) {
        const MapReader m(r_, node, "disk", {"type", "center", "normal", "radius", "material"});
        if (place.group >= 0) r_.fail(node, "a disk cannot be in a group (it cannot move yet)");
        scene_.shapes.of<Disk>().push_back(
            {m.vec3("center"), unit_or_zero(m.direction("normal")), m.positive_up_to("radius", Limits::max_radius),
             material_index(m, scene_)});
    }

    void read_plane(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "plane", {"type", "name", "normal", "distance", "material"});
        named.name = name(m);
        named.kind = SurfaceKind::plane;
        const dvec3 normal = m.direction("normal");
        const double distance = m.number("distance");
        // n.x = d and (n/s).x = d/s are the same plane: scale both alike.
        const double scale = max_abs_component(normal);
        const double length = glm::length(normal / scale);
        named.index = scene_.planes.size();
        named.local_plane = {unit_or_zero(normal), distance / scale / length, material_index(m, scene_)};
        scene_.planes.push_back(named.local_plane);
        if (place.group >= 0) place_surface(scene_, named, place.world);
    }

    // `type: triangle` and `type: mesh`: world-space triangles.
    void read_triangles(const YAML::Node& node, const Place& place, NamedSurface& named, bool is_mesh) {
        const MapReader m = is_mesh
            ? MapReader(r_, node, "mesh", {"type", "name", "file", "material", "transform", "smooth"})
            : MapReader(r_, node, "triangle", {"type", "name", "vertices", "material"});
        named.name = name(m);
        named.kind = is_mesh ? SurfaceKind::mesh : SurfaceKind::triangle;
        const int material = material_index(m, scene_);
        if (is_mesh && m.has("transform")) named.transform = read_transform(r_, m.value("transform"));
        const glm::dmat4 world = place.world * named.transform.matrix();
        if (place.group >= 0 || is_mesh) check_usable(m, world);
        if (is_mesh && !load(m).colors.empty()) {
            // Vertex colours: the world's own triangles carry none, so the
            // file is a mesh of the scene, this surface an instance of it
            // (its zero-area triangles counted for each surface, as below).
            scene_.degenerate_mesh_triangles += load(m).degenerate_dropped;
            named.kind = SurfaceKind::instance;
            named.colored_mesh = true;
            named.index = scene_.instances.size();
            scene_.instances.push_back({colored_mesh(m), material, world});
            return;
        }
        PlacedMesh placed;
        Mesh mesh = is_mesh ? read_mesh(m, material, place.group < 0 ? named.transform.matrix() : world, placed)
                            : read_triangle(m, material);
        if (!is_mesh) placed = place.group < 0 ? fh::place(mesh, named.transform) : fh::place(mesh, world);
        named.index = scene_.triangles.size();
        named.count = placed.triangles.size();
        add_triangles(scene_, placed);
        named.mesh = std::make_shared<const Mesh>(std::move(mesh));
    }

    // A mesh file (meshes/mesh_loader.h), read once however many surfaces
    // name it. Triangles the transform collapses to zero area are dropped
    // (and counted) like the file's own.
    Mesh read_mesh(const MapReader& m, int material, const glm::dmat4& to_world, PlacedMesh& placed) {
        const MeshData& data = load(m);
        Mesh mesh{data.positions, data.normals, data.triangles, material, m.boolean_or("smooth", false), {}, {}, {}, {}, false};
        placed = fh::place(mesh, to_world);
        size_t kept = 0;
        for (size_t i = 0; i < mesh.triangles.size(); ++i) {
            if (placed.triangles[i].degenerate()) continue;
            mesh.triangles[kept] = mesh.triangles[i];
            placed.triangles[kept] = placed.triangles[i];
            if (mesh.smooth) placed.vertex_normals[kept] = placed.vertex_normals[i];
            ++kept;
        }
        scene_.degenerate_mesh_triangles += data.degenerate_dropped + (mesh.triangles.size() - kept);
        mesh.triangles.resize(kept);
        placed.triangles.resize(kept);
        if (mesh.smooth) placed.vertex_normals.resize(kept);
        return mesh;
    }

    // The scene mesh of a `type: mesh` file with vertex colours (one for each
    // file and `smooth`, however many surfaces name it). It has no name: an
    // instance cannot name it, only the file does.
    int colored_mesh(const MapReader& m) {
        const std::string key = relative(m, "file").string() + (m.boolean_or("smooth", false) ? "|smooth" : "");
        const auto [it, added] = colored_meshes_.try_emplace(key, int(scene_.meshes.size()));
        if (added) scene_.meshes.push_back({"", scene_mesh(m)});
        return it->second;
    }

    // A mesh file in its own space, for instances to place (each with its
    // own material): its file and `smooth` from m.
    std::shared_ptr<Mesh> scene_mesh(const MapReader& m) {
        const MeshData& data = load(m);
        return std::make_shared<Mesh>(Mesh{data.positions, data.normals, data.triangles, 0,
                                           m.boolean_or("smooth", false), {}, data.colors, {}, {}, false});
    }

    void read_instance(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "instance", {"type", "name", "mesh", "material", "transform"});
        named.name = name(m);
        named.kind = SurfaceKind::instance;
        const int mesh = mesh_index(m);
        if (m.has("transform")) named.transform = read_transform(r_, m.value("transform"));
        const glm::dmat4 world = place.world * named.transform.matrix();
        check_usable(m, world);
        named.index = scene_.instances.size();
        scene_.instances.push_back({mesh, material_index(m, scene_), world});
    }

    void read_instances(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "instances", {"type", "name", "mesh", "material", "placements", "transform"});
        named.name = name(m);
        named.kind = SurfaceKind::instances;
        const int mesh = mesh_index(m), material = material_index(m, scene_);
        if (m.has("transform")) named.transform = read_transform(r_, m.value("transform"));
        const std::string csv = relative(m, "placements").string();
        const Placements placements = load_placements(csv);
        const std::vector<Transform>& rows = placements.rows;
        if (scene_.instances.size() + rows.size() > kMaxInstances)
            r_.fail(m.value("placements"), "more than " + std::to_string(kMaxInstances) + " instances in the scene");
        auto rows_matrices = std::make_shared<std::vector<glm::dmat4>>();
        rows_matrices->reserve(rows.size());
        const glm::dmat4 world = place.world * named.transform.matrix();
        named.index = scene_.instances.size();
        named.count = rows.size();
        // Room for the rows, not twice what they need (growth doubles), yet
        // still amortized over many sets.
        std::vector<Instance>& all = scene_.instances;
        if (all.size() + rows.size() > all.capacity())
            all.reserve(std::max(all.size() + rows.size(), all.capacity() + all.capacity() / 2));
        for (size_t k = 0; k < rows.size(); ++k) {
            rows_matrices->push_back(rows[k].matrix());
            const glm::dmat4 to_world = world * rows_matrices->back();
            if (const std::string why = unusable_transform(to_world); !why.empty())
                throw InputError(csv, placements.lines[k], 1, why + " (the row placed by its set and groups)");
            scene_.instances.push_back({mesh, material, to_world});
        }
        // The rows are kept only where a movie may move the set, or its group.
        if (!named.name.empty() || place.group >= 0) named.local_placements = std::move(rows_matrices);
    }

    void read_group(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "group", {"type", "name", "transform", "surfaces"});
        named.name = name(m);
        named.kind = SurfaceKind::group;
        Group g;
        g.name = named.name;
        g.parent = place.group;
        if (m.has("transform")) g.transform = read_transform(r_, m.value("transform"));
        named.transform = g.transform;
        const glm::dmat4 world = place.world * g.transform.matrix();
        check_usable(m, world);
        named.index = scene_.groups.size();
        scene_.groups.push_back(std::move(g));
        scene_.named_surfaces.push_back(named);  // before its members: parents first
        if (m.has("surfaces")) read_list(m.value("surfaces"), Place{int(named.index), world});
    }

    // A glTF file: its nodes under a group of this name and transform
    // (gltf/gltf_loader.h), its animations for a movie to play.
    void read_gltf(const YAML::Node& node, const Place& place, NamedSurface& named) {
        const MapReader m(r_, node, "gltf", {"type", "name", "file", "transform", "exposure"});
        named.name = name(m);
        named.kind = SurfaceKind::group;
        if (m.has("transform")) named.transform = read_transform(r_, m.value("transform"));
        check_usable(m, place.world * named.transform.matrix());
        const double exposure = m.has("exposure") ? m.number_at_least("exposure", 0) : 1.0;
        if (exposure > kMaxExposure) r_.fail(m.value("exposure"), "'exposure' must be at most 1e6 (as --exposure)");
        GltfFile file = load_gltf(relative(m, "file").string(), exposure);
        if (warnings_) warnings_->insert(warnings_->end(), file.warnings.begin(), file.warnings.end());
        named.index = scene_.groups.size();  // add_gltf's first group: the placement
        const std::string group = named.name.empty() ? "gltf" : named.name;
        std::vector<std::string> taken;
        for (const std::string* name : names_from(0, 0, 0)) taken.push_back(*name);
        const size_t cameras = scene_.cameras.size(), suns = scene_.directional_lights.size(),
                     spots = scene_.spot_lights.size();
        std::vector<NodeAnimation> animations = add_gltf(scene_, std::move(file), group, named.transform, place.group);
        // Its cameras and lights are named as its materials are, GROUP/NAME:
        // a file placed twice is no clash of the names a movie or --camera
        // picks by. (Within one file names may repeat, as glTF allows.)
        for (std::string* name : names_from(cameras, suns, spots)) {
            *name = group + "/" + *name;
            if (std::find(taken.begin(), taken.end(), *name) != taken.end())
                r_.fail(m.value("file"), "a second camera or light named '" + *name +
                                             "' (give each glTF surface a name of its own)");
        }
        if (animations_)
            for (NodeAnimation& a : animations) animations_->push_back(std::move(a));
        scene_.named_surfaces.push_back(named);
    }

    // The names of the cameras and lights from these positions on.
    std::vector<std::string*> names_from(size_t cameras, size_t suns, size_t spots) {
        std::vector<std::string*> names;
        for (size_t k = cameras; k < scene_.cameras.size(); ++k) names.push_back(&scene_.cameras[k].name);
        for (size_t k = suns; k < scene_.directional_lights.size(); ++k)
            names.push_back(&scene_.directional_lights[k].name);
        for (size_t k = spots; k < scene_.spot_lights.size(); ++k) names.push_back(&scene_.spot_lights[k].name);
        return names;
    }

    // The name of a surface: unique among the surfaces.
    std::string name(const MapReader& m) {
        if (!m.has("name")) return "";
        const std::string name = r_.string(m.value("name"), "name");
        if (name.empty()) r_.fail(m.value("name"), "a surface's 'name' must not be empty");
        if (!names_.insert(name).second) r_.fail(m.value("name"), "a second surface named '" + name + "'");
        return name;
    }

    int mesh_index(const MapReader& m) const {
        const YAML::Node node = m.value("mesh");
        const std::string name = r_.string(node, "mesh");
        for (size_t i = 0; i < scene_.meshes.size(); ++i)
            if (!name.empty() && scene_.meshes[i].name == name) return int(i);
        std::vector<std::string> names;
        for (const SceneMesh& s : scene_.meshes)
            if (!s.name.empty()) names.push_back(s.name);
        const std::string hint = closest_match(name, names);
        if (!hint.empty()) r_.fail(node, "undefined mesh '" + name + "' (did you mean '" + hint + "'?)");
        if (names.empty()) r_.fail(node, "undefined mesh '" + name + "' (meshes are named in the scene's 'meshes:' section)");
        // None close: the names there are (the first few).
        std::string known;
        for (size_t i = 0; i < names.size() && i < 4; ++i) known += (i ? ", " : "") + names[i];
        if (names.size() > 4) known += ", ...";
        r_.fail(node, "undefined mesh '" + name + "' (the scene's meshes: " + known + ")");
    }

    void check_usable(const MapReader& m, const glm::dmat4& to_world) const {
        const std::string why = unusable_transform(to_world);
        if (why.empty()) return;
        r_.fail(m.has("transform") ? m.value("transform") : m.node(), why);
    }

    std::filesystem::path relative(const MapReader& m, const std::string& key) const {
        return std::filesystem::path(r_.file()).parent_path() / r_.file_name(m.value(key), key);
    }

    // A mesh file's data, read once per scene whatever names it.
    const MeshData& load(const MapReader& m) {
        const std::string path = relative(m, "file").string();
        auto it = files_.find(path);
        if (it == files_.end()) {
            it = files_.emplace(path, load_mesh(path)).first;
            ++scene_.mesh_files;
        }
        return it->second;
    }

    const YamlReader& r_;
    Scene& scene_;
    std::vector<NodeAnimation>* animations_;
    std::vector<std::string>* warnings_;
    std::unordered_set<std::string> names_;
    std::map<std::string, MeshData> files_;
    std::map<std::string, int> colored_meshes_;  // colored_mesh's, by file and smooth
};

}  // namespace

Transform read_transform(const YamlReader& r, const YAML::Node& node) {
    const MapReader m(r, node, "'transform'", {"scale", "rotate", "translate"});
    Transform t;
    if (m.has("translate")) t.translate = m.vec3("translate");
    if (const MapReader::Entry* rot = m.find("rotate")) {
        const MapReader q(r, rot->value, "'rotate'", {"axis", "degrees", "radians"});
        if (q.has("degrees") && q.has("radians"))
            r.fail(rot->value, "'rotate' gives its angle twice: 'degrees' or 'radians', not both");
        if (!q.has("degrees") && !q.has("radians"))
            r.fail(rot->value, "'rotate' needs an angle: 'degrees' or 'radians' (one of them)");
        t.radians = q.has("degrees") ? glm::radians(q.number("degrees")) : q.number("radians");
        t.axis = q.direction("axis");
    }
    if (const MapReader::Entry* sc = m.find("scale")) {
        t.scale = sc->value.IsSequence() ? m.vec3("scale") : dvec3(m.number("scale"));
        if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0)
            r.fail(sc->value, "'scale' must not be 0 (a number, or one per axis; a negative one mirrors)");
    }
    return t;
}

int material_index(const MapReader& m, const Scene& scene) {
    const YAML::Node node = m.value("material");
    const std::string name = m.reader().string(node, "material");
    const auto& names = scene.material_names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
        const std::string hint = closest_match(name, names);
        m.reader().fail(node, "undefined material '" + name + "'" +
                                  (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    return static_cast<int>(it - names.begin());
}

void read_meshes_and_surfaces(const YamlReader& reader, const YAML::Node& meshes, const YAML::Node& surfaces,
                              Scene& scene, std::vector<NodeAnimation>& animations, std::vector<std::string>& warnings) {
    SurfaceReader surfaces_reader(reader, scene, &animations, &warnings);
    if (!meshes.IsNull()) surfaces_reader.read_meshes(meshes);
    surfaces_reader.read_list(surfaces, Place{});
}

}  // namespace fh
