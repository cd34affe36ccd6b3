// firsthit info FILE: what a scene, movie or glTF file holds, as key: value
// lines (the encode script reads a movie's fps from it); --camera, --frame,
// --animation, --fps and --exposure as render takes them.
#include <iostream>
#include <vector>

#include "anim/frame_selection.h"
#include "anim/movie.h"
#include "gltf/gltf_loader.h"
#include "gltf/gltf_movie.h"
#include "cli/commands.h"
#include "cli/args.h"
#include "cli/job.h"
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
    // (A mesh no instance places -- a morphed or skinned mesh's rest pose,
    // whose instances place their own deformed copies -- is not traced.)
    size_t distinct = 0, instanced = 0;
    std::vector<bool> placed(s.meshes.size(), false);
    for (const Instance& i : s.instances) {
        instanced += s.meshes[size_t(i.mesh)].mesh->triangles.size();
        placed[size_t(i.mesh)] = true;
    }
    for (size_t m = 0; m < s.meshes.size(); ++m)
        if (placed[m]) distinct += s.meshes[m].mesh->triangles.size();
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


// The frame --frame picks in m (checked), or -1 without it.
int chosen_frame(const Movie& m, const JobRequest& request) {
    return request.frame ? parse_int(*request.frame, "--frame", 0, m.frame_count() - 1) : -1;
}

// The lines a movie and a glTF file share; with a frame (>= 0), it and its
// time.
void print_movie(const std::string& kind, const Movie& m, int frame) {
    std::cout << "kind: " << kind << "\n"
              << "frames: " << m.frame_count() << "\n"
              << "fps: " << m.fps << "\n"
              << "seconds: " << m.seconds << "\n"
              << "camera: " << m.camera.name << "\n"
              << "width: " << m.camera.width << "\n"
              << "height: " << m.camera.height << "\n"
              << "first_frame_file: " << FrameFiles{}.name(0, m.frame_count()) << "\n";
    if (frame >= 0) {
        std::cout << "frame: " << frame << "\n"
                  << "time: " << frame / m.fps << "\n";
    }
}
}  // namespace

int run_info(const Args& args) {
    JobRequest request = job_request_from_args(args);
    const std::string& file = request.file;
    if (is_gltf_file(file)) {
        const double exposure = request.exposure.value_or(1);
        GltfScene g = gltf_scene(file, exposure);
        std::vector<std::string> animations;
        for (const NodeAnimation& a : g.animations) animations.push_back(a.name);
        const Movie m = gltf_movie(std::move(g), {file, request.camera, request.animation, request.fps.value_or(30),
                                                  exposure});
        print_movie("gltf", m, chosen_frame(m, request));  // checked before anything is printed
        std::cout << "nodes: " << m.scene.nodes.size() << "\n"
                  << "animations:";
        for (const std::string& a : animations) std::cout << " '" << a << "'";
        size_t skinned = 0, morphed = 0;  // meshes a node deforms (scene/deformation.h)
        for (const Deformation& d : m.scene.deformations) skinned += d.skin.weights != nullptr, morphed += d.targets != nullptr;
        size_t cutouts = 0, see_through = 0;
        for (const Material<double>& mat : m.scene.materials) cutouts += mat.cutout, see_through += mat.blend;
        std::cout << "\nskinned_meshes: " << skinned << "\nmorphed_meshes: " << morphed
                  << "\ntextures: " << m.scene.textures.size() << "\ncutout_materials: " << cutouts
                  << "\nsee_through_materials: " << see_through << "\n";
        print_scene(m.scene, m.settings);
        return 0;
    }
    // A scene or movie file, its flags checked as render checks them.
    request.check_cameras = false;
    request.movie_camera_note = "info shows the camera it films with";
    const Job job = load_job(request);  // before printing: an error prints nothing else
    // Every frame's values checked as render and frames check them (scripts
    // ask info whether a movie will render; its warnings are theirs to say).
    if (job.is_movie_file) {
        check_movie_cameras(file, job.movie);
        print_movie("movie", job.movie, job.frame >= 0 && request.frame ? job.frame : -1);
    } else {
        std::cout << "kind: scene\n";
        if (request.camera)
            std::cout << "camera: " << job.camera.name << "\nwidth: " << job.camera.width << "\nheight: "
                      << job.camera.height << "\n";
    }
    print_scene(job.movie.scene, job.movie.settings);
    return 0;
}

}  // namespace fh
