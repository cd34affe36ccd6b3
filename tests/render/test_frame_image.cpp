// A frame's image is not zeroed before the tiles write it (render/image.h),
// so every tile must write every one of its pixels. Each frame here is
// rendered twice, right after a block of its image's size was filled with
// 0xCD and freed, then after one filled with zeros: the allocator hands that
// block out again, so a pixel no tile wrote would differ between the two.
#include <gtest/gtest.h>

#include <algorithm>

#include "yaml/scene_loader.h"
#include "render/prepared_scene.h"

namespace fh {
namespace {

Bytes render_after(const PreparedScene& prepared, const Camera& camera, std::uint8_t fill) {
    {
        Bytes left(std::size_t(camera.width) * std::size_t(camera.height) * 3);
        std::fill(left.begin(), left.end(), fill);
        asm volatile("" : : "r"(left.data()) : "memory");  // the fill must happen
    }
    return prepared.render(camera, nullptr).image.rgb;
}

TEST(FrameImage, EveryPixelIsWrittenWhateverTheMemoryHeld) {
    const SceneFile loaded = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml");
    Camera camera = loaded.scene.cameras[0];
    camera.width = 37;  // tiles and packets cut by the right and bottom edges
    camera.height = 23;
    for (const Precision p : {Precision::float32, Precision::float64})
        for (const int spp : {1, 3})
            for (const bool adaptive : {false, true}) {
                RenderSettings settings = loaded.settings;
                settings.precision = p;
                settings.samples_per_pixel = spp;
                settings.adaptive = adaptive;
                const PreparedScene prepared(loaded.scene, settings);
                const Bytes over_cd = render_after(prepared, camera, 0xCD);
                const Bytes over_zeros = render_after(prepared, camera, 0);
                EXPECT_EQ(over_cd, over_zeros) << "spp " << spp << (adaptive ? ", adaptive" : "")
                                               << ", " << precision_name(p);
            }
}

}  // namespace
}  // namespace fh
