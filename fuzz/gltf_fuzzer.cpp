// libFuzzer target: the glTF loader on arbitrary bytes, as JSON (.gltf) or
// as GLB (bytes starting "glTF"), with an empty folder beside it, so every
// uri but data: finds nothing (scripts/fuzz.sh). An accepted file is placed
// as `firsthit render MODEL.glb` places it -- default camera and lights --
// its animations evaluated at their first and last frames, and rendered tiny.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "anim/movie.h"
#include "fuzz_common.h"
#include "gltf/gltf_loader.h"
#include "gltf/gltf_movie.h"

namespace {

std::string g_folder;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("firsthit_gltf_fuzzer_" + std::to_string(getpid()));
    fs::create_directories(dir);
    g_folder = dir.string();
    static const struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code ec;
            fs::remove_all(dir, ec);
        }
    } cleanup{dir};
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    fh::Movie movie;
    try {
        fh::GltfFile file = fh::load_gltf_from_memory(bytes, g_folder + "/fuzz.gltf", g_folder);
        const bool has_lights = !file.scene.directional_lights.empty() || !file.scene.spot_lights.empty();
        const std::vector<fh::NodeAnimation> animations =
            fh::add_gltf(movie.scene, std::move(file), "model", fh::Transform{});
        if (movie.scene.cameras.empty()) fh::add_default_camera(movie.scene);
        fh::add_default_lights(movie.scene, movie.scene.cameras.front(), 1, !has_lights);
        movie.camera = movie.scene.cameras.front();
        movie.node_channels = fh::chosen_channels(animations, "all", "fuzz.gltf");
    } catch (const fh::InputError& e) {
        fh::fuzz::check_message(e);
        return 0;
    }
    // Any other exception escapes and is reported as a crash.
    double end = 0;
    for (const fh::NodeChannel& c : movie.node_channels) end = std::max(end, c.sampler.end());
    movie.fps = 30;
    movie.seconds = std::min(end, 60.0) + 1 / 30.0;
    const int n = movie.frame_count();
    for (const int frame : {0, n - 1}) {
        fh::Scene scene = movie.scene;
        fh::scene_at(movie, frame, scene);
        fh::fuzz::render_tiny(scene, fh::camera_at(movie, frame), fh::RenderSettings{});
    }
    return 0;
}
