// firsthit info FILE: what a scene or movie file holds, as key: value lines
// (the encode script reads a movie's fps from it).
#include <iostream>

#include "anim/frame_selection.h"
#include "anim/movie.h"
#include "gltf/gltf_loader.h"
#include "gltf/gltf_movie.h"
#include "cli/commands.h"
#include "cli/args.h"
#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "yaml/scene_loader.h"
#include "pipeline/frame_files.h"
#include "render/levels.h"

namespace fh {

namespace {
void print_scene(const Scene& s, const RenderSettings& settings) {
    std::cout << "materials: " << s.materials.size() << "\n"
              << "spheres: " << s.spheres().size() << "\n"
              << "planes: " << s.planes.size() << "\n"
              << "triangles: " << s.triangles.size() << "\n"
              << "meshes: " << s.mesh_files << "\n"
              << "degenerate_triangles_dropped: " << s.degenerate_mesh_triangles << "\n";
    // Instances share their mesh's triangles: distinct ones are what memory
    // holds, instanced ones what the picture shows.
    size_t distinct = 0, instanced = 0;
    for (const SceneMesh& m : s.meshes) distinct += m.mesh->triangles.size();
    for (const Instance& i : s.instances) instanced += s.meshes[size_t(i.mesh)].mesh->triangles.size();
    std::cout << "shared_meshes: " << s.meshes.size() << "\n"
              << "instances: " << s.instances.size() << "\n"
              << "groups: " << s.groups.size() << "\n"
              << "distinct_triangles: " << s.triangles.size() + distinct << "\n"
              << "instanced_triangles: " << instanced << "\n"
              << "lights:";
    for (const auto& l : s.ambient_lights) std::cout << " " << l.name << (l.on ? "" : "(off)");
    for (const auto& l : s.directional_lights) std::cout << " " << l.name << (l.on ? "" : "(off)");
    for (const auto& l : s.spot_lights) std::cout << " " << l.name << (l.on ? "" : "(off)");
    std::cout << "\ncameras:";
    for (const auto& c : s.cameras) std::cout << " " << c.name;
    std::cout << "\nsamples_per_pixel: " << settings.samples_per_pixel << "\n"
              << "max_depth: " << settings.max_depth << "\n"
              << "effects: " << settings.effects.names() << "\n"
              << "tracer_level: " << level_name(level_in_use()) << "\n";  // render/levels.h
}


// The lines a movie and a glTF file share.
void print_movie(const std::string& kind, const Movie& m) {
    std::cout << "kind: " << kind << "\n"
              << "frames: " << m.frame_count() << "\n"
              << "fps: " << m.fps << "\n"
              << "seconds: " << m.seconds << "\n"
              << "camera: " << m.camera.name << "\n"
              << "width: " << m.camera.width << "\n"
              << "height: " << m.camera.height << "\n"
              << "first_frame_file: " << FrameFiles{}.name(0, m.frame_count()) << "\n";
}
}  // namespace

int run_info(const Args& args) {
    if (args.positional().size() != 1) throw UsageError("expected one FILE");
    const std::string file = args.positional()[0];
    if (is_gltf_file(file)) {
        GltfScene g = gltf_scene(file);
        std::vector<std::string> animations;
        for (const NodeAnimation& a : g.animations) animations.push_back(a.name);
        const Movie m = gltf_movie(std::move(g), {file, std::nullopt, std::nullopt, 30, 1});
        print_movie("gltf", m);
        std::cout << "nodes: " << m.scene.nodes.size() << "\n"
                  << "animations:";
        for (const std::string& a : animations) std::cout << " '" << a << "'";
        size_t skinned = 0, morphed = 0;  // meshes a node deforms (scene/deformation.h)
        for (const Deformation& d : m.scene.deformations) skinned += d.skin.weights != nullptr, morphed += d.targets != nullptr;
        size_t cutouts = 0;
        for (const Material<double>& mat : m.scene.materials) cutouts += mat.cutout;
        std::cout << "\nskinned_meshes: " << skinned << "\nmorphed_meshes: " << morphed
                  << "\ntextures: " << m.scene.textures.size() << "\ncutout_materials: " << cutouts << "\n";
        print_scene(m.scene, m.settings);
        return 0;
    }
    if (is_movie_file(file)) {
        const Movie m = load_movie(file);
        print_movie("movie", m);
        print_scene(m.scene, m.settings);
    } else {
        const SceneFile scene = load_scene(file);  // before printing: an error prints nothing else
        std::cout << "kind: scene\n";
        print_scene(scene.scene, scene.settings);
    }
    return 0;
}

}  // namespace fh
