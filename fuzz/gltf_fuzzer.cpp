// libFuzzer target: the glTF loader on arbitrary bytes, as JSON (.gltf) or
// as GLB (bytes starting "glTF"), with an empty folder beside it, so every
// uri but data: finds nothing (scripts/fuzz.sh). An accepted file is placed
// as `firsthit render MODEL.glb` places it -- default camera and lights --
// its animations evaluated at their first and last frames, and rendered tiny.
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
    g_folder = fh::fuzz::private_folder("gltf_fuzzer").string();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    fh::Movie movie;
    try {
        fh::GltfScene g = fh::gltf_scene(fh::load_gltf_from_memory(bytes, g_folder + "/fuzz.gltf", g_folder));
        movie.scene = std::move(g.scene);
        movie.camera = movie.scene.cameras.front();
        movie.node_channels = fh::chosen_channels(g.animations, "all", "fuzz.gltf");
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
