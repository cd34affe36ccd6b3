// How the glTF loader maps a file's cameras, lights, materials and
// animations onto the report's model (docs/gltf.md), each expected value
// worked out by hand from that page's formulas and the glTF 2.0
// specification. A rotation written [0, 0, H, H] (H = sin 45°) is a quarter
// turn about z: x -> y, y -> -x.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gltf/gltf_load.h"
#include "gltf/gltf_movie.h"
#include "scene/camera.h"

namespace fh {
namespace {

using namespace gltf_test;

void expect_camera(const Camera& c, Projection projection, double distance, double half_height, int width, int height) {
    EXPECT_EQ(c.projection, projection) << c.name;
    EXPECT_NEAR(c.projection_distance, distance, 1e-9) << c.name;
    EXPECT_NEAR(c.half_height, half_height, 1e-12) << c.name;
    EXPECT_EQ(c.width, width) << c.name;
    EXPECT_EQ(c.height, height) << c.name;
}

template <typename Light>
void expect_light(const Light& l, const std::string& name, const dvec3& color, double intensity) {
    EXPECT_EQ(l.name, name);
    expect_vec(l.color, color);
    EXPECT_NEAR(l.intensity, intensity, 1e-15) << name;
}

// A material against values worked out by hand (its ambient always the
// report's 0.1).
struct Shading {
    dvec3 color, specular_color;
    double diffuse, specular, exponent;
    bool glazed;
    double reflectivity;
};
void expect_shading(const Material<double>& m, const Shading& want) {
    expect_vec(m.ambient_color, want.color, 1e-9);
    expect_vec(m.diffuse_color, want.color, 1e-9);
    expect_vec(m.specular_color, want.specular_color, 1e-9);
    EXPECT_EQ(m.ambient, 0.1);
    EXPECT_NEAR(m.diffuse, want.diffuse, 1e-12);
    EXPECT_NEAR(m.specular, want.specular, 1e-12);
    EXPECT_NEAR(m.phong_exponent, want.exponent, 1e-6);
    EXPECT_EQ(m.glazed, want.glazed);
    EXPECT_NEAR(m.reflectivity, want.reflectivity, 1e-12);
}

// ------------------------------------------------------------------ cameras

TEST(GltfCameras, PerspectiveAndOrthographicByTheDocumentedFormula) {
    // Perspective: d = 10 / tan(yfov / 2): yfov 90° -> 10, 60° -> 10 sqrt 3;
    // 800 / aspectRatio tall, 600 without one. Orthographic: h = ymag,
    // 800 ymag / xmag tall.
    const GltfFile f = load(gltf_json(R"("scenes": [{"nodes": [0, 1, 2]}], "nodes": [{"camera": 0}, {"camera": 1}, {"camera": 2}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1.5707963267948966, "aspectRatio": 2, "znear": 0.1}},
                    {"type": "perspective", "name": "wide", "perspective": {"yfov": 1.0471975511965976, "znear": 0.1}},
                    {"type": "orthographic", "orthographic": {"xmag": 4, "ymag": 3, "znear": 0.1, "zfar": 100}}])"));
    ASSERT_EQ(f.scene.cameras.size(), 3u);
    EXPECT_EQ(f.scene.cameras[0].name, "camera 0");
    EXPECT_EQ(f.scene.cameras[1].name, "wide");
    expect_camera(f.scene.cameras[0], Projection::perspective, 10, 10, 800, 400);
    expect_camera(f.scene.cameras[1], Projection::perspective, 17.320508075688775, 10, 800, 600);
    expect_camera(f.scene.cameras[2], Projection::orthographic, 10, 3, 800, 600);  // d unused: the default
}

// An image 800 wide must be 1 to 16384 tall: an aspect ratio past that is
// the file's mistake, said so (1e-9 once made an 800 x 16384 image).
TEST(GltfCameras, AnAspectRatioPastTheImageLimitsIsAnError) {
    auto with = [](const std::string& camera) {
        return gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{"camera": 0}], "cameras": [)" + camera + "]");
    };
    expect_input_error([&] { load(with(R"({"type": "perspective", "perspective": {"yfov": 1, "aspectRatio": 1e-9, "znear": 0.1}})")); },
                       "t.gltf", "camera 0: aspectRatio would make the image 800 wide and 800000000000 tall (1 to 16384)");
    expect_input_error([&] { load(with(R"({"type": "perspective", "perspective": {"yfov": 1, "aspectRatio": 2000, "znear": 0.1}})")); },
                       "t.gltf", "camera 0: aspectRatio would make the image 800 wide and 0 tall (1 to 16384)");
    expect_input_error([&] { load(with(R"({"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 100, "znear": 0.1, "zfar": 9}})")); },
                       "t.gltf", "camera 0: xmag / ymag would make the image 800 wide and 80000 tall (1 to 16384)");
    EXPECT_EQ(load(with(R"({"type": "perspective", "perspective": {"yfov": 1, "aspectRatio": 0.0488281, "znear": 0.1}})"))
                  .scene.cameras[0].height, 16384);
}

TEST(GltfCameras, ACameraLooksDownItsNodesMinusZWithItsPlusYUp) {
    // Parent moves (1,2,0), child (0,0,3) turned 90° about y (z -> x, x -> -z):
    // eye (1,2,3), looking R(0,0,-1) = (-1,0,0), up R(0,1,0) = (0,1,0).
    const std::string json = gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{"translation": [1,2,0], "children": [1]},
        {"camera": 0, "translation": [0,0,3], "rotation": [0,0.7071067811865476,0,0.7071067811865476]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1, "znear": 0.1}}])");
    const GltfFile f = placed(json);
    ASSERT_EQ(f.scene.cameras.size(), 1u);
    EXPECT_EQ(f.scene.cameras[0].node, 1);
    expect_vec(f.scene.cameras[0].view_point, {1, 2, 3});
    expect_vec(f.scene.cameras[0].look_at, {-1, 0, 0});
    expect_vec(f.scene.cameras[0].up, {0, 1, 0});
    // Placed z-up, (x, y, z) -> (x, -z, y).
    const Scene s = z_up(json);
    expect_vec(s.cameras[0].view_point, {1, -3, 2});
    expect_vec(s.cameras[0].look_at, {-1, 0, 0});
    expect_vec(s.cameras[0].up, {0, 0, 1});
}

// The rays the report's camera casts for glTF cameras on the node of the
// test above (placed z-up: eye (1,-3,2) looking along -x, up +z, so the
// image's right is +y). Perspective, yfov 90° and aspectRatio 2 (800 x 400):
// the top edge's middle is 45° above the view axis, the right edge's middle
// at tan = 2 x tan 45° beside it. Orthographic, xmag 4 and ymag 3: rays
// along -x from the eye moved 3 up and 4 right.
TEST(GltfCameras, RaysThroughTheImageEdgesAreTheFieldOfViewsEdges) {
    auto camera = [](const std::string& camera) {
        const Scene s = z_up(gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{"translation": [1,2,0], "children": [1]},
            {"camera": 0, "translation": [0,0,3], "rotation": [0,0.7071067811865476,0,0.7071067811865476]}],
            "cameras": [)" + camera + "]"));
        return s.cameras.at(0);
    };
    const Camera p = camera(R"({"type": "perspective", "perspective": {"yfov": 1.5707963267948966, "aspectRatio": 2, "znear": 0.1}})");
    ASSERT_EQ(p.width, 800);
    ASSERT_EQ(p.height, 400);
    const CameraRays<double> rays(p);
    auto direction = [&](double px, double py) { return rays.generate(px, py).direction; };
    expect_vec(rays.generate(0, 0).origin, {1, -3, 2}, 1e-12);
    expect_vec(direction(400, 200), {-1, 0, 0}, 1e-12);
    expect_vec(direction(400, 0), glm::normalize(dvec3(-1, 0, 1)), 1e-12);
    expect_vec(direction(800, 200), glm::normalize(dvec3(-1, 2, 0)), 1e-12);
    expect_vec(direction(0, 400), glm::normalize(dvec3(-1, -2, -1)), 1e-12);

    const Camera o = camera(R"({"type": "orthographic", "orthographic": {"xmag": 4, "ymag": 3, "znear": 0.1, "zfar": 100}})");
    ASSERT_EQ(o.height, 600);
    const CameraRays<double> flat(o);
    expect_vec(flat.generate(400, 0).origin, {1, -3, 5}, 1e-12);
    expect_vec(flat.generate(800, 300).origin, {1, 1, 2}, 1e-12);
    expect_vec(flat.generate(0, 600).origin, {1, -7, -1}, 1e-12);
    expect_vec(flat.generate(0, 600).direction, {-1, 0, 0}, 1e-12);
}

TEST(GltfCameras, AFileWithoutACameraGetsTheDefaultFramingItsBox) {
    // The triangle z-up: (0,0,0) (1,0,0) (0,0,1); box centre (0.5, 0, 0.5),
    // its sphere's radius sqrt 2 / 2. 45° tall: d = 10 / tan 22.5° = 10 (1 +
    // sqrt 2); the eye radius / sin 22.5° / 0.9 = 2.0530656 from the centre,
    // along (0.35, -1, 0.45) / 1.1510864: (1.1242563, -1.7835894, 1.3026152),
    // in front (glTF's +z is -y), a little right and above.
    TempFolder dir("default_camera");
    Bin bin;
    const GltfScene g = gltf_scene(dir.write("tri.gltf", gltf_json(triangle_body(bin), bin)));
    ASSERT_EQ(g.scene.cameras.size(), 1u);
    const Camera& c = g.scene.cameras[0];
    EXPECT_EQ(c.name, "default");
    expect_camera(c, Projection::perspective, 24.14213562373095, 10, 800, 600);
    expect_vec(c.view_point, {1.1242563049019478, -1.783589442576994, 1.3026152491596474}, 1e-9);
    expect_vec(glm::normalize(c.look_at), glm::normalize(dvec3(0.5, 0, 0.5) - c.view_point), 1e-12);  // at the centre
    expect_vec(c.up, {0, 0, 1});
}

// ------------------------------------------------------------------- lights

const char* kThreeLights = R"("extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "color": [1, 0.5, 0], "intensity": 2},
        {"type": "point", "name": "bulb", "intensity": 10},
        {"type": "spot", "intensity": 5, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}}]}},
    "scenes": [{"nodes": [0, 1, 2]}], "nodes": [
        {"rotation": [0.7071067811865476,0,0,0.7071067811865476], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"translation": [0,4,0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"translation": [1,0,0], "rotation": [0,0.7071067811865476,0,0.7071067811865476],
         "extensions": {"KHR_lights_punctual": {"light": 2}}}])";

TEST(GltfLights, PunctualLightsInTheDocumentedUnits) {
    // Exposure 3. Directional: 255 c = (255, 127.5, 0), 3 x 2 lux / 255, along
    // the node's -z turned 90° about x (y -> z, z -> -y): (0, 1, 0). Point: a
    // spot with no cone at (0,4,0), 3 x 10 cd / 255. Spot: 3 x 5 / 255, its
    // cone the outer angle 0.6, along -z turned 90° about y: (-1, 0, 0).
    const GltfFile f = placed(gltf_json(kThreeLights), 3);
    ASSERT_EQ(f.scene.directional_lights.size(), 1u);
    expect_light(f.scene.directional_lights[0], "light 0", {255, 127.5, 0}, 6.0 / 255);
    expect_vec(f.scene.directional_lights[0].direction, {0, 1, 0});
    ASSERT_EQ(f.scene.spot_lights.size(), 2u);
    const auto& point = f.scene.spot_lights[0];
    expect_light(point, "bulb", {255, 255, 255}, 30.0 / 255);
    expect_vec(point.position, {0, 4, 0});
    EXPECT_TRUE(std::isinf(point.max_angle) && point.max_angle > 0);
    const auto& spot = f.scene.spot_lights[1];
    expect_light(spot, "light 2", {255, 255, 255}, 15.0 / 255);
    EXPECT_DOUBLE_EQ(spot.max_angle, 0.6);
    EXPECT_DOUBLE_EQ(spot.inner_angle, 0.2);  // lit fully out to innerConeAngle
    EXPECT_TRUE(spot.gltf_cone);             // then KHR_lights_punctual's falloff
    EXPECT_EQ(point.inner_angle, 0);
    EXPECT_FALSE(point.gltf_cone);
    expect_vec(spot.position, {1, 0, 0});
    expect_vec(spot.axis, {-1, 0, 0});
    // Exposure 1: the lux and candela alone.
    const GltfFile one = load(gltf_json(kThreeLights));
    EXPECT_NEAR(one.scene.directional_lights[0].intensity, 2.0 / 255, 1e-15);
    EXPECT_NEAR(one.scene.spot_lights[0].intensity, 10.0 / 255, 1e-15);
    // Placed z-up, the directional light's (0,1,0) is (0,0,1).
    expect_vec(z_up(gltf_json(kThreeLights)).directional_lights[0].direction, {0, 0, 1});
}

TEST(GltfLights, AFileWithoutLightsGetsTheKeyAndAmbientTimesExposure) {
    // Exposure 2: ambient 2 x 1.5 / 255 (0.15 of a colour at the materials'
    // ambient strength of 0.1), key 2 x 1 lux / 255, both white. The
    // key travels along -w - 0.8 v + 0.5 u of the camera's basis (w =
    // -look_at, u = up x w, v = w x u), over |(0.5, -0.8, -1)| = sqrt 1.89: its
    // parts 0.3636965 along u (right), -0.5819144 along v (down), 0.7273930
    // along the view.
    TempFolder dir("default_lights");
    Bin bin;
    const GltfScene g = gltf_scene(dir.write("tri.gltf", gltf_json(triangle_body(bin), bin)), 2);
    ASSERT_EQ(g.scene.ambient_lights.size(), 1u);
    expect_light(g.scene.ambient_lights[0], "ambient", {255, 255, 255}, 3.0 / 255);
    ASSERT_EQ(g.scene.directional_lights.size(), 1u);
    const auto& key = g.scene.directional_lights[0];
    expect_light(key, "key", {255, 255, 255}, 2.0 / 255);
    const Camera& c = g.scene.cameras[0];
    const dvec3 w = -glm::normalize(c.look_at), u = glm::normalize(glm::cross(c.up, w)), v = glm::cross(w, u);
    EXPECT_NEAR(glm::dot(key.direction, u), 0.363696483726654, 1e-9);
    EXPECT_NEAR(glm::dot(key.direction, v), -0.5819143739626463, 1e-9);
    EXPECT_NEAR(glm::dot(key.direction, -w), 0.727392967453308, 1e-9);
    EXPECT_TRUE(g.scene.spot_lights.empty());
    // A file with lights of its own gets the ambient light and no key.
    const GltfScene lit = gltf_scene(dir.write("lit.gltf", gltf_json(kThreeLights)), 2);
    EXPECT_EQ(lit.scene.ambient_lights.size(), 1u);
    ASSERT_EQ(lit.scene.directional_lights.size(), 1u);
    EXPECT_EQ(lit.scene.directional_lights[0].name, "light 0");
}

// ---------------------------------------------------------------- materials

TEST(GltfMaterials, MetallicRoughnessByTheDocumentedFormula) {
    // c = 255 base; specular colour m c + (1 - m) 255; diffuse (1 - m) + m r;
    // specular (0.04 + 0.96 m)(1 - r); exponent 2 / a^2 - 2, a = max(r^2, 0.01),
    // at most 10,000; glazed when m > 0.5 and r < 0.5, reflectivity m (1 - r)^2.
    const GltfFile f = load(gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{}], "materials": [
        {"name": "matte", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.2, 0.3], "metallicFactor": 0, "roughnessFactor": 1}},
        {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.6, 0.4, 1], "metallicFactor": 1, "roughnessFactor": 0.2}},
        {"pbrMetallicRoughness": {"metallicFactor": 0.3, "roughnessFactor": 0.5}},
        {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1], "metallicFactor": 0.6, "roughnessFactor": 0.05}}])"));
    ASSERT_EQ(f.scene.materials.size(), 5u);  // and glTF's default, last
    EXPECT_EQ(f.scene.material_names[0], "matte");
    EXPECT_EQ(f.scene.material_names[1], "material 1");
    // m = 0, r = 1 (alpha unused): a white highlight of strength 0, exponent 2 / 1 - 2 = 0.
    expect_shading(f.scene.materials[0], {{255, 127.5, 51}, {255, 255, 255}, 1, 0, 0, false, 0});
    // m = 1, r = 0.2: the highlight tinted, diffuse 0.2, specular 0.8, a =
    // 0.04: 2 / 0.0016 - 2 = 1248; glazed, reflectivity 0.8^2 = 0.64.
    expect_shading(f.scene.materials[1], {{204, 153, 102}, {204, 153, 102}, 0.2, 0.8, 1248, true, 0.64});
    // m = 0.3, r = 0.5, white: diffuse 0.7 + 0.15 = 0.85, specular 0.328 x 0.5
    // = 0.164, a = 0.25: 2 / 0.0625 - 2 = 30; not glazed (m <= 0.5), so no
    // reflectivity (docs/gltf.md's m (1 - r)^2 = 0.075 is a glazed material's).
    expect_shading(f.scene.materials[2], {{255, 255, 255}, {255, 255, 255}, 0.85, 0.164, 30, false, 0});
    // m = 0.6, r = 0.05, blue: specular colour 0.6 (0,0,255) + 0.4 x 255 =
    // (102, 102, 255); diffuse 0.4 + 0.03; specular 0.616 x 0.95 = 0.5852; a =
    // max(0.0025, 0.01): 2 / 0.0001 - 2 = 19998, capped at 10,000; glazed,
    // reflectivity 0.6 x 0.95^2 = 0.5415.
    expect_shading(f.scene.materials[3], {{0, 0, 255}, {102, 102, 255}, 0.43, 0.5852, 10000, true, 0.5415});
}

TEST(GltfMaterials, EmissiveIs255TimesFactorTimesStrength) {
    const GltfFile f = load(gltf_json(R"("extensionsUsed": ["KHR_materials_emissive_strength"],
        "scenes": [{"nodes": [0]}], "nodes": [{}], "materials": [{"emissiveFactor": [0.2, 0.4, 0]},
        {"emissiveFactor": [1, 0.5, 0], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}])"));
    expect_vec(f.scene.materials[0].emissive, {51, 102, 0}, 1e-12);
    expect_vec(f.scene.materials[1].emissive, {1020, 510, 0}, 1e-12);
    expect_vec(f.scene.materials[2].emissive, {0, 0, 0});  // the default gives off nothing
}

TEST(GltfMaterials, APrimitiveWithoutAMaterialGetsGltfsDefault) {
    // White, m = r = 1: specular colour c, diffuse 0 + 1 x 1, specular 0, exponent 0.
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const GltfFile f = load(gltf_json(R"("materials": [{"name": "used"}], "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}, {"attributes": {"POSITION": 0}}]}],
        "accessors": [)" + accessor(p, kFloat, 3, "VEC3") + "]", bin));
    ASSERT_EQ(f.scene.instances.size(), 2u);
    EXPECT_EQ(f.scene.instances[0].material, 0);
    EXPECT_EQ(f.scene.instances[1].material, 1);
    EXPECT_EQ(f.scene.material_names[1], "glTF default");
    expect_shading(f.scene.materials[1], {{255, 255, 255}, {255, 255, 255}, 1, 0, 0, false, 0});
}

// ---------------------------------------------------------------- animation

TEST(GltfAnimation, ChannelsOfDifferentLengthsShareOneClock) {
    // Node 0's translation: keys at 0 and 1, (0,0,0) to (2,0,0). Node 1's
    // scale: keys at 0, 2, 4: (1,1,1), (2,2,2), (3,3,3). The animation lasts 4.
    Bin bin;
    const int t2 = bin.f32({0, 1}), v2 = bin.f32({0, 0, 0, 2, 0, 0}), t3 = bin.f32({0, 2, 4}),
              v3 = bin.f32({1, 1, 1, 2, 2, 2, 3, 3, 3});
    const std::string more = ", " + joined({accessor(t2, kFloat, 2, "SCALAR"), accessor(v2, kFloat, 2, "VEC3"),
                                            accessor(t3, kFloat, 3, "SCALAR"), accessor(v3, kFloat, 3, "VEC3")});
    GltfFile f = load(gltf_json(triangle_mesh(bin, more) + R"(, "scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0}, {"mesh": 0}], )" +
                                    animation(joined({channel(0, 0, "translation"), channel(1, 1, "scale")}),
                                              joined({sampler(1, 2, "LINEAR"), sampler(3, 4, "LINEAR")})),
                                bin));
    ASSERT_EQ(f.animations.size(), 1u);
    const NodeAnimation& a = f.animations[0];
    EXPECT_EQ(a.name, "animation 0");
    EXPECT_EQ(a.start(), 0);
    EXPECT_EQ(a.end(), 4);  // the longest channel's last key
    auto at = [&](double t, dvec3 translation, dvec3 scale) {
        apply_channels(a.channels, t, f.scene);
        expect_vec(f.scene.nodes[0].translation, translation);
        expect_vec(f.scene.nodes[1].scale, scale);
    };
    at(-1, {0, 0, 0}, {1, 1, 1});  // before the first keys: the first values
    at(0.5, {1, 0, 0}, {1.25, 1.25, 1.25});
    at(3, {2, 0, 0}, {2.5, 2.5, 2.5});  // the shorter channel holds its last key
    at(10, {2, 0, 0}, {3, 3, 3});
    place_nodes(f.scene);
    expect_vec(apply(f.scene.instances[1].to_world, {1, 0, 0}), {3, 0, 0});
}

TEST(GltfAnimation, StepLinearAndCubicSplineTranslationsFromTheFile) {
    // Keys at 0, 1, 2 on x: 1, 2, 3. STEP at 0.99 still 1; LINEAR at 1.5 is 2.5.
    // CUBICSPLINE keys at 0 and 2, each (in-tangent, value, out-tangent):
    // ((100), (0), (1)) and ((3), (4), (-100)); the interval 2 scales the
    // tangents, so at s = t / 2: x = h10(s) 2 x 1 + h01(s) 4 + h11(s) 2 x 3.
    // s = 0.5: 0.125 x 2 + 0.5 x 4 - 0.125 x 6 = 1.5; s = 0.25: 0.140625 x 2 +
    // 0.15625 x 4 - 0.046875 x 6 = 0.625. (The tangents 100 and -100 are never used.)
    Bin bin;
    const int t = bin.f32({0, 1, 2}), v = bin.f32({1, 0, 0, 2, 0, 0, 3, 0, 0}), tc = bin.f32({0, 2}),
              vc = bin.f32({100, 0, 0, 0, 0, 0, 1, 0, 0, 3, 0, 0, 4, 0, 0, -100, 0, 0});
    const std::string more = ", " + joined({accessor(t, kFloat, 3, "SCALAR"), accessor(v, kFloat, 3, "VEC3"),
                                            accessor(tc, kFloat, 2, "SCALAR"), accessor(vc, kFloat, 6, "VEC3")});
    GltfFile f = load(gltf_json(triangle_mesh(bin, more) + R"(, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0}, {"mesh": 0}, {"mesh": 0}], )" +
                                    animation(joined({channel(0, 0, "translation"), channel(1, 1, "translation"),
                                                      channel(2, 2, "translation")}),
                                              joined({sampler(1, 2, "STEP"), sampler(1, 2, "LINEAR"), sampler(3, 4, "CUBICSPLINE")})),
                                bin));
    ASSERT_EQ(f.animations.size(), 1u);
    const struct { double time; size_t node; double x; } keys[] = {
        {0.99, 0, 1}, {1, 0, 2}, {1.5, 0, 2},                                // STEP
        {0.25, 1, 1.25}, {1.5, 1, 2.5},                                      // LINEAR
        {0, 2, 0}, {0.5, 2, 0.625}, {1, 2, 1.5}, {2, 2, 4}, {3, 2, 4}};      // CUBICSPLINE
    for (const auto& k : keys) {
        apply_channels(f.animations[0].channels, k.time, f.scene);
        EXPECT_NEAR(f.scene.nodes[k.node].translation.x, k.x, 1e-12) << "node " << k.node << " at " << k.time;
    }
}

TEST(GltfAnimation, AnAnimatedCameraAndLightMoveWithTheirNodes) {
    // The camera's node moves from (0,0,0) to (0,0,-10) over 2 s: at 1 s
    // (0,0,-5), z-up (0,5,0). The light's node turns from none to 90° about
    // y over 1 s: -z goes to (-sin a, 0, -cos a): at 1 s (-1, 0, 0); at 0.5 s
    // (a = 45°) (-H, 0, -H), z-up (-H, H, 0).
    Bin bin;
    const double h = kHalfSqrt2;
    const int t = bin.f32({0, 2}), v = bin.f32({0, 0, 0, 0, 0, -10}), tr = bin.f32({0, 1}),
              r = bin.f32({0, 0, 0, 1, 0, 0.70710678f, 0, 0.70710678f});
    GltfFile f = load(gltf_json(R"("extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional"}]}},
        "scenes": [{"nodes": [0, 1]}], "nodes": [{"camera": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 1, "znear": 0.1}}], )" +
                                    animation(joined({channel(0, 0, "translation"), channel(1, 1, "rotation")}),
                                              joined({sampler(0, 1, "LINEAR"), sampler(2, 3, "LINEAR")})) +
                                    ", \"accessors\": [" +
                                    joined({accessor(t, kFloat, 2, "SCALAR"), accessor(v, kFloat, 2, "VEC3"),
                                            accessor(tr, kFloat, 2, "SCALAR"), accessor(r, kFloat, 2, "VEC4")}) + "]",
                                bin));
    Scene s;
    const std::vector<NodeAnimation> animations = add_gltf(s, std::move(f), "m", Transform{});
    ASSERT_EQ(animations.size(), 1u);
    apply_channels(animations[0].channels, 1, s);
    place_nodes(s);
    expect_vec(s.cameras[0].view_point, {0, 5, 0});
    expect_vec(s.directional_lights[0].direction, {-1, 0, 0}, 1e-7);
    apply_channels(animations[0].channels, 0.5, s);
    place_nodes(s);
    expect_vec(s.cameras[0].view_point, {0, 2.5, 0});
    expect_vec(s.directional_lights[0].direction, {-h, h, 0}, 1e-7);
}

// Ten nested nodes each animated to a scale of 1e38 hold the triangle: the
// product, 1e380, is past a double. Each value is finite, so the file
// loads; at 1 s the instance shows nothing (as a scale of 0), never
// infinities, and at 0 s it is where the file puts it.
TEST(GltfAnimation, ScalesMultiplyingPastADoubleShowNothing) {
    Bin bin;
    const int t = bin.f32({0, 1}), v = bin.f32({1, 1, 1, 1e38f, 1e38f, 1e38f});
    const std::string more = ", " + joined({accessor(t, kFloat, 2, "SCALAR"), accessor(v, kFloat, 2, "VEC3")});
    std::string nodes, channels;
    for (int i = 0; i < 10; ++i) {
        nodes += "{\"children\": [" + std::to_string(i + 1) + "]}, ";
        channels += (i ? ", " : "") + channel(0, i, "scale");
    }
    GltfFile f = load(gltf_json(triangle_mesh(bin, more) + R"(, "scenes": [{"nodes": [0]}], "nodes": [)" + nodes +
                                    R"({"mesh": 0}], )" + animation(channels, sampler(1, 2, "LINEAR")),
                                bin));
    ASSERT_EQ(f.scene.instances.size(), 1u);
    apply_channels(f.animations[0].channels, 1, f.scene);
    place_nodes(f.scene);
    const glm::dmat4& m = f.scene.instances[0].to_world;
    for (int k = 0; k < 16; ++k) EXPECT_EQ(m[k / 4][k % 4], k == 15 ? 1.0 : 0.0) << "element " << k;
    apply_channels(f.animations[0].channels, 0, f.scene);
    place_nodes(f.scene);
    expect_matrix(f.scene.instances[0].to_world, {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
}

}  // namespace
}  // namespace fh
