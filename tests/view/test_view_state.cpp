// The viewer's logic without a window (src/view/view_state.h): P's rule,
// frame stepping, playback's clock, the resolution divisor, saved names and
// the title. The window itself is tested by tests/view/test_view.sh.
#include <gtest/gtest.h>

#include "yaml/movie_loader.h"
#include "yaml/scene_loader.h"
#include "view/view_state.h"

namespace fh::view {
namespace {

Camera cam(const std::string& name, Projection p) {
    Camera c;
    c.name = name;
    c.projection = p;
    return c;
}

Scene scene_of_cameras(std::vector<Camera> cams) {
    Scene s;
    s.cameras = std::move(cams);
    return s;
}

TEST(ViewState, PSwitchesToTheNextCameraWithTheOtherProjection) {
    const Scene s = scene_of_cameras({cam("p1", Projection::perspective), cam("p2", Projection::perspective),
                                cam("o1", Projection::orthographic)});
    ViewState v("dir/scene.yaml", s, 0);
    EXPECT_EQ(v.camera().name, "p1");
    EXPECT_TRUE(v.switch_camera());
    EXPECT_EQ(v.camera().name, "o1");  // p2 skipped: same projection
    EXPECT_TRUE(v.switch_camera());
    EXPECT_EQ(v.camera().name, "p1");  // wraps around
}

TEST(ViewState, PWithOneProjectionCyclesAndWithOneCameraDoesNothing) {
    const Scene two = scene_of_cameras({cam("a", Projection::perspective), cam("b", Projection::perspective)});
    ViewState v("s.yaml", two, 1);
    EXPECT_TRUE(v.switch_camera());
    EXPECT_EQ(v.camera().name, "a");
    const Scene one = scene_of_cameras({cam("only", Projection::orthographic)});
    ViewState w("s.yaml", one, 0);
    EXPECT_FALSE(w.switch_camera());
    EXPECT_EQ(w.camera().name, "only");
}

TEST(ViewState, SceneFileHasOneFrameAndNamesItsSave) {
    const Scene s = scene_of_cameras({cam("perspective", Projection::perspective)});
    ViewState v("animations/scene.yaml", s, 0);
    EXPECT_FALSE(v.is_movie());
    EXPECT_EQ(v.frame_count(), 1);
    EXPECT_FALSE(v.step(+1));
    EXPECT_FALSE(v.end());
    EXPECT_EQ(v.save_name(), "view_scene_perspective.png");
    EXPECT_EQ(v.title(800, 800, 84.4, false), "firsthit view: scene.yaml | perspective | 800x800 | 84 ms");
}

TEST(ViewState, MovieStepsClampAndPFlipsTheProjectionKeepingThePath) {
    const Movie m = load_movie(FIRSTHIT_SOURCE_DIR "/animations/movie1.yaml");
    ViewState v("animations/movie1.yaml", m, 0);
    ASSERT_TRUE(v.is_movie());
    EXPECT_EQ(v.frame_count(), 300);
    EXPECT_FALSE(v.step(-1));
    EXPECT_EQ(v.frame(), 0);
    EXPECT_TRUE(v.step(+1));
    EXPECT_EQ(v.frame(), 1);
    EXPECT_TRUE(v.end());
    EXPECT_EQ(v.frame(), 299);
    EXPECT_FALSE(v.step(+1));
    EXPECT_TRUE(v.set_frame(42));

    const Camera before = v.camera();
    EXPECT_EQ(before.projection, Projection::perspective);
    EXPECT_EQ(v.save_name(), "view_movie1_frame0042_perspective.png");
    EXPECT_TRUE(v.switch_camera());
    const Camera after = v.camera();
    EXPECT_EQ(after.projection, Projection::orthographic);
    EXPECT_EQ(after.view_point, camera_at(m, 42).view_point);
    EXPECT_EQ(after.look_at, camera_at(m, 42).look_at);
    EXPECT_EQ(after.name, "perspective-orthographic");
    EXPECT_EQ(v.save_name(), "view_movie1_frame0042_perspective-orthographic.png");
    EXPECT_EQ(v.title(200, 200, 12, true),
              "firsthit view: movie1.yaml | frame 42/299 | perspective-orthographic (orthographic) "
              "| 200x200 | 12 ms | playing");
    EXPECT_TRUE(v.switch_camera());
    EXPECT_EQ(v.camera().name, "perspective");
    EXPECT_EQ(v.camera().projection, Projection::perspective);
}

TEST(ViewState, ReducedKeepsTheViewAndAtLeastOnePixel) {
    Camera c = cam("c", Projection::perspective);
    c.width = 800;
    c.height = 600;
    EXPECT_EQ(reduced(c, 4).width, 200);
    EXPECT_EQ(reduced(c, 4).height, 150);
    EXPECT_EQ(reduced(c, 1).width, 800);
    EXPECT_EQ(reduced(c, 1000).width, 1);
    EXPECT_EQ(reduced(c, 1000).height, 1);
    EXPECT_EQ(reduced(c, 4).view_point, c.view_point);
}

TEST(ViewState, PlaybackFollowsTheClockAndLoops) {
    EXPECT_EQ(frame_at(0, 0.0, 30, 300), 0);
    EXPECT_EQ(frame_at(0, 1.0, 30, 300), 30);
    EXPECT_EQ(frame_at(10, 0.5, 30, 300), 25);
    EXPECT_EQ(frame_at(290, 1.0, 30, 300), 20);  // wraps
    EXPECT_EQ(frame_at(5, -1.0, 30, 300), 5);
    EXPECT_EQ(frame_at(0, 1e6, 30, 300), int((30LL * 1000000) % 300));
}

TEST(ViewState, DivisorDropsWhenBehindAndRisesWhenWellAhead) {
    // 30 fps: 33.3 ms per frame.
    EXPECT_EQ(adapt_divisor(1, 80, 30), 2);
    EXPECT_EQ(adapt_divisor(2, 40, 30), 4);
    EXPECT_EQ(adapt_divisor(16, 400, 30), 16);  // at the floor
    EXPECT_EQ(adapt_divisor(4, 20, 30), 4);     // keeps up: stay
    EXPECT_EQ(adapt_divisor(4, 5, 30), 2);      // 4x the cost still fits
    EXPECT_EQ(adapt_divisor(1, 1, 30), 1);
}

}  // namespace
}  // namespace fh::view
