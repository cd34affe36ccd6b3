// libFuzzer target: the movie loader on arbitrary bytes (scripts/fuzz.sh).
// The input is the movie file; it names its scene relative to a temporary
// folder holding a fixed, valid scene.yaml (two cameras, three lights).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "anim/movie.h"
#include "fuzz_common.h"
#include "yaml/movie_loader.h"

namespace {

std::string g_movie_path;

const char* const kScene = R"(materials:
  red: {color: [255, 19, 1], ambient: 0.1, diffuse: 0.5, specular: 1.5, phong_exponent: 10}
  teal: {color: [20, 255, 255], ambient: 0.1, diffuse: 0.3, specular: 10, phong_exponent: 100,
         glazed: true, reflectivity: 0.3}
surfaces:
  - {type: sphere, center: [-3, 0, 0], radius: 1, material: red}
  - {type: plane, normal: [0, 0, 1], distance: -1, material: teal}
  - {type: triangle, vertices: [[-5, 5, 0], [-7, 5, 0], [-6, 7, 0]], material: red}
lights:
  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.002}
  sun: {type: directional, color: [255, 255, 230], intensity: 0.02, direction: [-50, 50, -50]}
  spot: {type: spot, color: [255, 255, 255], intensity: 2.2, position: [0, 0, 10],
         direction: [0, 0, -1], max_angle: 0.785}
cameras:
  perspective: {type: perspective, width: 8, height: 8, view_point: [2, -10, 10],
                look_at: [0, 2, -1], up: [0, 0, 1], projection_distance: 10}
  orthographic: {type: orthographic, width: 8, height: 6, view_point: [2, -10, 10],
                 look_at: [0, 2, -1], up: [0, 0, 1]}
)";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const std::filesystem::path dir = fh::fuzz::private_folder("movie_fuzzer");
    std::ofstream(dir / "scene.yaml") << kScene;
    g_movie_path = (dir / "movie.yaml").string();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fh::Movie movie;
    try {
        movie = fh::load_movie_from_string(text, g_movie_path);
    } catch (const fh::InputError& e) {
        fh::fuzz::check_message(e);
        return 0;
    }
    const int n = movie.frame_count();
    if (n < 1) std::abort();  // the loader guarantees at least one frame
    // The paths at a few frames (all of them, checked, for short movies),
    // and the first frame rendered tiny when its values passed the checks.
    try {
        if (n <= 64) fh::check_animations(movie);
    } catch (const std::invalid_argument&) {
        return 0;  // reported by the CLI as bad input
    }
    for (const int frame : {0, n / 3, n / 2, n - 1}) (void)fh::camera_at(movie, frame);
    const fh::Camera cam = fh::camera_at(movie, 0);
    fh::Scene scene = movie.scene;
    fh::scene_at(movie, 0, scene);  // every animated property at frame 0
    if (n <= 64 && fh::is_finite(cam.look_at) && fh::max_abs_component(cam.look_at) > 0)
        fh::fuzz::render_tiny(scene, cam, movie.settings);
    return 0;
}
