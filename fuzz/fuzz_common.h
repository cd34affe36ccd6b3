// What every fuzzer checks besides "no crash, no leak, no hang": a loader
// either returns or throws fh::InputError, whose message is one line; and an
// accepted scene renders (at 4 x 4 pixels, to stay fast) without crashing.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "text/input_error.h"
#include "render/render.h"
#include "scene/scene.h"

namespace fh::fuzz {

// Aborts (a crash, for libFuzzer) when a message is not one printable line.
inline void check_message(const InputError& e) {
    const std::string line = e.formatted();
    for (const char c : line) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            std::fprintf(stderr, "error message with a control character: %s\n", line.c_str());
            std::abort();
        }
    }
    if (line.size() > 6000) {
        std::fprintf(stderr, "error message of %zu bytes\n", line.size());
        std::abort();
    }
}

// A folder of this fuzzer's own under the system's temporary folder
// ("firsthit_NAME_PID"), removed when the fuzzer exits normally.
inline std::filesystem::path private_folder(const std::string& name) {
    namespace fs = std::filesystem;
    static const struct Folder {
        fs::path dir;
        ~Folder() {
            std::error_code ec;
            fs::remove_all(dir, ec);
        }
    } folder{fs::temp_directory_path() / ("firsthit_" + name + "_" + std::to_string(::getpid()))};
    fs::create_directories(folder.dir);
    return folder.dir;
}

// Renders the camera at 4 x 4 with at most 2 samples and depth 3: every
// accepted value goes through the tracer once.
inline void render_tiny(const Scene& scene, Camera camera, RenderSettings settings) {
    camera.width = 4;
    camera.height = 4;
    settings.samples_per_pixel = std::min(settings.samples_per_pixel, 2);
    settings.max_depth = std::min(settings.max_depth, 3);
    const FrameResult r = render_frame(scene, camera, settings, nullptr);
    if (r.image.rgb.size() != 4u * 4u * 3u) std::abort();
}

}  // namespace fh::fuzz
