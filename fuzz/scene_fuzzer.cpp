// libFuzzer target: the scene loader on arbitrary bytes (scripts/fuzz.sh).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_common.h"
#include "yaml/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fh::SceneFile file;
    try {
        file = fh::load_scene_from_string(text, "fuzz_scene.yaml");
    } catch (const fh::InputError& e) {
        fh::fuzz::check_message(e);
        return 0;
    }
    // Any other exception escapes and is reported as a crash.
    for (const fh::Camera& camera : file.scene.cameras) fh::fuzz::render_tiny(file.scene, camera, file.settings);
    return 0;
}
