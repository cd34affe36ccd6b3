#include "gltf/gltf_cameras_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gltf/gltf_model.h"
#include "render/settings.h"
#include "scene/camera.h"
#include "text/input_error.h"

namespace fh {

// glTF cameras onto the report's (docs/gltf.md): the image plane 2 h
// tall at distance d, so tan(yfov / 2) = h / d; an orthographic camera
// sees ymag above and below its axis.
Camera gltf_camera(const tinygltf::Camera& c, int index, int node, const std::string& file) {
    auto fail = [&](const std::string& what) { throw InputError(file, what); };
    Camera cam;
    cam.name = c.name.empty() ? "camera " + std::to_string(index) : c.name;
    cam.node = node;
    cam.width = 800;
    // 800 wide and this tall, within the image limits: a file's extreme
    // aspect ratio (1e-9 once made an 800 x 16384 image without a word) is
    // an error, not a clamp.
    auto height_for = [&](double aspect, const std::string& what) {
        const double h = std::round(800 / aspect);
        if (!(h >= 1 && h <= Limits::max_image_side))
            fail(cam.name + ": " + what + " would make the image 800 wide and " +
                 std::to_string(std::llround(std::min(h, 1e18))) + " tall (1 to " +
                 std::to_string(Limits::max_image_side) + ")");
        return int(h);
    };
    if (c.type == "orthographic") {
        const double xmag = c.orthographic.xmag, ymag = c.orthographic.ymag;
        if (!(xmag > 0) || !(ymag > 0) || !std::isfinite(xmag) || !std::isfinite(ymag))
            fail(cam.name + ": xmag and ymag must be > 0");
        cam.projection = Projection::orthographic;
        cam.half_height = ymag;
        cam.height = height_for(xmag / ymag, "xmag / ymag");
    } else if (c.type == "perspective") {
        const double yfov = c.perspective.yfov, aspect = c.perspective.aspectRatio;
        if (!(yfov > 0 && yfov < std::numbers::pi)) fail(cam.name + ": yfov must be in (0, pi)");
        cam.projection = Projection::perspective;
        cam.projection_distance = 10 / std::tan(yfov / 2);
        cam.height = aspect > 0 && std::isfinite(aspect) ? height_for(aspect, "aspectRatio") : 600;
    } else {
        fail(cam.name + ": camera type '" + c.type + "' is not perspective or orthographic");
    }
    return cam;
}

// KHR_lights_punctual onto the report's lights (docs/gltf.md): colour
// 255 c; intensity exposure x lux (directional) or candela (point, spot)
// / 255, so 1 lux on a white surface facing it is 255. A spot's cone
// ends at outerConeAngle; a point light is a spot with no cone.
void add_gltf_light(const tinygltf::Light& l, int index, int node, double exposure, Scene& s, const std::string& file) {
    auto fail = [&](const std::string& what) { throw InputError(file, what); };
    const std::string name = l.name.empty() ? "light " + std::to_string(index) : l.name;
    const dvec3 color = 255.0 * glm::clamp(vec3_or(l.color, dvec3(1)), 0.0, 1.0);
    if (!(l.intensity >= 0) || !std::isfinite(l.intensity)) fail(name + ": intensity must be >= 0");
    const double intensity = exposure * l.intensity / 255;
    if (intensity > Limits::max_strength)
        fail(name + ": intensity " + std::to_string(l.intensity) + " (times exposure, / 255) is past the limit of 1e12");
    if (l.type == "directional") {
        DirectionalLight<double> d;
        d.name = name;
        d.color = color;
        d.intensity = intensity;
        d.node = node;
        s.directional_lights.push_back(d);
    } else if (l.type == "point" || l.type == "spot") {
        SpotLight<double> spot;
        spot.name = name;
        spot.color = color;
        spot.intensity = intensity;
        spot.node = node;
        spot.max_angle = l.type == "point" ? kInfinity<double> : l.spot.outerConeAngle;
        // (0, pi/2] by the extension; pi/2 written as a float rounds a little past it.
        if (!(spot.max_angle > 0) || (l.type == "spot" && spot.max_angle > double(float(std::numbers::pi / 2))))
            fail(name + ": outerConeAngle must be in (0, pi/2]");
        if (l.type == "spot" && !(l.spot.innerConeAngle >= 0 && l.spot.innerConeAngle < l.spot.outerConeAngle))
            fail(name + ": innerConeAngle must be in [0, outerConeAngle)");
        if (l.type == "spot") spot.inner_angle = l.spot.innerConeAngle, spot.gltf_cone = true;
        s.spot_lights.push_back(spot);
    } else {
        fail(name + ": light type '" + l.type + "' is not directional, point or spot");
    }
}

void add_default_camera(Scene& scene) {
    Aabb box;
    for (const Instance& i : scene.instances)
        for (const dvec3& p : scene.meshes[size_t(i.mesh)].mesh->positions) box.grow(dvec3(i.to_world * glm::dvec4(p, 1.0)));
    for (const auto& t : scene.triangles) box.grow(t.v0), box.grow(t.v1), box.grow(t.v2);
    for (const auto& s : scene.spheres()) box.grow(s.center - s.radius), box.grow(s.center + s.radius);
    const dvec3 center = box.empty() ? dvec3(0) : box.center();
    const double radius = box.empty() ? 1 : std::max(0.5 * glm::length(box.hi - box.lo), 1e-9);
    Camera c;
    c.name = "default";
    c.width = 800;
    c.height = 600;
    // 45 degrees tall; far enough that the bounding sphere's sine is 0.9 of
    // the half angle's: tan(asin(0.9 sin 22.5°)) / tan 22.5° = 88.6% of the height.
    const double yfov = std::numbers::pi / 4;
    c.projection_distance = 10 / std::tan(yfov / 2);
    const dvec3 from = glm::normalize(dvec3(0.35, -1, 0.45));
    c.view_point = center + from * (radius / std::sin(yfov / 2) / 0.9);
    c.look_at = -from;
    c.up = {0, 0, 1};
    scene.cameras.push_back(c);
}

void add_default_lights(Scene& scene, const Camera& camera, double exposure, bool key_light) {
    // Against the materials' ambient strength of 0.1: 0.15 of a surface's colour.
    scene.ambient_lights.push_back({"ambient", dvec3(255), 1.5 * exposure / 255});
    if (!key_light) return;
    // 1 lux travelling as the camera looks, and down and to the right: from
    // behind its upper left.
    const CameraBasis b = camera_basis(camera.look_at, camera.up);
    DirectionalLight<double> key;
    key.name = "key";
    key.color = dvec3(255);
    key.intensity = exposure / 255;
    key.direction = glm::normalize(-b.w - 0.8 * b.v + 0.5 * b.u);
    scene.directional_lights.push_back(key);
}

}  // namespace fh
