// `up` parallel to the view direction gives a valid basis by
// the documented rule of scene/camera.h (the coordinate axis least aligned with
// the view direction stands in for `up`), with no NaN anywhere in the image;
// a zero-length look_at is an input error.
#include <gtest/gtest.h>

#include <cmath>

#include "text/input_error.h"
#include "yaml/scene_loader.h"
#include "robust_util.h"
#include "scene/camera.h"
#include "test_util.h"

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class CameraDegenerate : public ::testing::Test {};
TYPED_TEST_SUITE(CameraDegenerate, Scalars);

void expect_orthonormal(const CameraBasis& b, const dvec3& look_at) {
    for (const dvec3& v : {b.u, b.v, b.w}) {
        ASSERT_TRUE(is_finite(v));
        EXPECT_NEAR(glm::length(v), 1, 1e-12);
    }
    EXPECT_NEAR(glm::dot(b.u, b.v), 0, 1e-12);
    EXPECT_NEAR(glm::dot(b.u, b.w), 0, 1e-12);
    EXPECT_NEAR(glm::dot(b.v, b.w), 0, 1e-12);
    // Right-handed, and w looks back along look_at.
    EXPECT_NEAR(glm::dot(glm::cross(b.u, b.v), b.w), 1, 1e-12);
    EXPECT_NEAR(glm::dot(b.w, -glm::normalize(look_at)), 1, 1e-12);
}

TEST(CameraDegenerateBasis, UpParallelOrAntiparallelAnyLength) {
    const dvec3 dirs[] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, -3, 0}, {1, 2, 3}, {-1e-3, 1e-3, 5}};
    for (const dvec3& look : dirs) {
        for (const double k : {1.0, -1.0, 1e-200, 1e200, -7.5}) {
            const dvec3 up = k * glm::normalize(look);
            const CameraBasis b = camera_basis(look, up);
            EXPECT_TRUE(b.up_was_parallel) << "look " << look.x << "," << look.y << "," << look.z;
            expect_orthonormal(b, look);
        }
        // A zero `up` has no direction either: the same rule.
        const CameraBasis z = camera_basis(look, dvec3(0));
        EXPECT_TRUE(z.up_was_parallel);
        expect_orthonormal(z, look);
    }
}

TEST(CameraDegenerateBasis, TheRuleIsTheLeastAlignedAxis) {
    // w = normalize(-(1,2,3)): x is least aligned, so u = normalize(x cross w).
    const dvec3 look(1, 2, 3);
    const CameraBasis b = camera_basis(look, look);
    const dvec3 w = glm::normalize(-look);
    const dvec3 u = glm::normalize(glm::cross(dvec3(1, 0, 0), w));
    EXPECT_NEAR(glm::length(b.u - u), 0, 1e-15);
    // Looking along (1,1,0): z is the least aligned axis.
    const CameraBasis t = camera_basis({1, 1, 0}, {2, 2, 0});
    EXPECT_NEAR(glm::length(t.u - glm::normalize(glm::cross(dvec3(0, 0, 1), glm::normalize(dvec3(-1, -1, 0))))),
                0, 1e-15);
    // Looking down z: x and y tie, x wins.
    const CameraBasis d = camera_basis({0, 0, -1}, {0, 0, 1});
    EXPECT_NEAR(glm::length(d.u - dvec3(0, -1, 0)), 0, 1e-15);
}

TEST(CameraDegenerateBasis, NearlyParallelUpStaysOrthonormal) {
    // up off the view direction by 1e-6 .. 1e-12 rad: either the real up or
    // the rule, but always a clean basis.
    for (const double a : {1e-6, 1e-8, 1e-9, 1e-10, 1e-12}) {
        const dvec3 look(0, 0, -1);
        const dvec3 up(std::sin(a), 0, std::cos(a));
        expect_orthonormal(camera_basis(look, up), look);
    }
}

// Rendered: the report's scene seen straight down and straight up with up
// along the view direction, and with up = 0; every sample finite, and the
// image is the same as with the rule's axis given as `up` explicitly.
TYPED_TEST(CameraDegenerate, RenderedImagesAreFinite) {
    using T = TypeParam;
    Scene s = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    for (const auto proj : {Projection::perspective, Projection::orthographic}) {
        for (const dvec3 look : {dvec3(0, 0, -1), dvec3(0, 0, 1), dvec3(0.3, -0.2, -1)}) {
            for (const dvec3 up : {glm::normalize(look), -2.0 * glm::normalize(look), dvec3(0)}) {
                const Camera cam = camera(proj, {-1, 1, 12}, look, up, 40);
                const auto r = render(s, cam, precision_of<T>(), all_effects());
                expect_finite_frame(r, "up parallel to the view");
                // Same picture as naming the rule's axis as `up`.
                const CameraBasis b = camera_basis(look, up);
                const dvec3 a = glm::abs(b.w);
                const dvec3 axis = (a.x <= a.y && a.x <= a.z) ? dvec3(1, 0, 0)
                                   : (a.y <= a.z)              ? dvec3(0, 1, 0)
                                                               : dvec3(0, 0, 1);
                const auto same = render(s, camera(proj, {-1, 1, 12}, look, axis, 40), precision_of<T>(),
                                         all_effects());
                EXPECT_EQ(count_differing_pixels(r.image, same.image), 0);
            }
        }
    }
}

TEST(CameraDegenerateInput, ZeroLookAtIsAnInputError) {
    for (const char* look : {"[0, 0, 0]", "[0.0, -0.0, 0]"}) {
        const std::string path = test::write_temp_file(
            "zero_look_at.yaml",
            std::string("cameras:\n  cam: {type: perspective, width: 8, height: 8, view_point: [0, 0, 5],\n"
                        "        look_at: ") +
                look + ", up: [0, 0, 1]}\n");
        try {
            load_scene(path);
            ADD_FAILURE() << "look_at " << look << " was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("'look_at' must not be zero-length"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace fh
