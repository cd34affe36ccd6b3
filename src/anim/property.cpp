#include "anim/property.h"

#include <cmath>

#include "render/settings.h"
#include "scene/instance.h"

namespace fh {

namespace {

template <typename Light>
auto& light(const Target& t, std::vector<Light>& lights) { return lights[t.index]; }

}  // namespace

std::vector<PropertyName> camera_properties(Projection projection) {
    std::vector<PropertyName> p = {{"view_point", Property::camera_view_point, ValueKind::point},
                                   {"look_at", Property::camera_look_at, ValueKind::direction},
                                   {"up", Property::camera_up, ValueKind::direction}};
    if (projection == Projection::perspective)
        p.push_back({"projection_distance", Property::camera_projection_distance, ValueKind::positive});
    return p;
}

std::vector<PropertyName> light_properties(LightKind kind) {
    std::vector<PropertyName> p = {{"on", Property::light_on, ValueKind::flag},
                                   {"intensity", Property::light_intensity, ValueKind::strength},
                                   {"color", Property::light_color, ValueKind::color}};
    if (kind != LightKind::ambient) p.push_back({"direction", Property::light_direction, ValueKind::direction});
    if (kind == LightKind::spot) {
        p.push_back({"position", Property::light_position, ValueKind::point});
        p.push_back({"max_angle", Property::light_max_angle, ValueKind::positive});
    }
    return p;
}

std::vector<PropertyName> surface_properties(SurfaceKind kind) {
    switch (kind) {
    case SurfaceKind::sphere:
        return {{"center", Property::sphere_center, ValueKind::point},
                {"radius", Property::sphere_radius, ValueKind::radius}};
    case SurfaceKind::plane:
        return {{"normal", Property::plane_normal, ValueKind::direction},
                {"distance", Property::plane_distance, ValueKind::number}};
    default:
        return {{"transform.translate", Property::transform_translate, ValueKind::point},
                {"transform.scale", Property::transform_scale, ValueKind::scale},
                {"transform.rotate.axis", Property::transform_axis, ValueKind::direction},
                {"transform.rotate.degrees", Property::transform_degrees, ValueKind::number},
                {"transform.rotate.radians", Property::transform_radians, ValueKind::number}};
    }
}

std::vector<PropertyName> material_properties() {
    return {{"color", Property::material_color, ValueKind::color},
            {"ambient_color", Property::material_ambient_color, ValueKind::color},
            {"diffuse_color", Property::material_diffuse_color, ValueKind::color},
            {"specular_color", Property::material_specular_color, ValueKind::color},
            {"ambient", Property::material_ambient, ValueKind::strength},
            {"diffuse", Property::material_diffuse, ValueKind::strength},
            {"specular", Property::material_specular, ValueKind::strength},
            {"phong_exponent", Property::material_phong_exponent, ValueKind::non_negative},
            {"reflectivity", Property::material_reflectivity, ValueKind::unit_interval}};
}

dvec3 value_of(const Target& t, const Scene& scene, const Camera& camera) {
    auto on_light = [&](auto&& read) -> dvec3 {
        if (t.light == LightKind::ambient) return read(scene.ambient_lights[t.index]);
        if (t.light == LightKind::directional) return read(scene.directional_lights[t.index]);
        return read(scene.spot_lights[t.index]);
    };
    const Material<double>* m = t.index < scene.materials.size() ? &scene.materials[t.index] : nullptr;
    const NamedSurface* s = t.index < scene.named_surfaces.size() ? &scene.named_surfaces[t.index] : nullptr;
    switch (t.property) {
    case Property::camera_view_point: return camera.view_point;
    case Property::camera_look_at: return camera.look_at;
    case Property::camera_up: return camera.up;
    case Property::camera_projection_distance: return dvec3(camera.projection_distance);
    case Property::light_on: return on_light([](const auto& l) { return dvec3(l.on ? 1 : 0); });
    case Property::light_intensity: return on_light([](const auto& l) { return dvec3(l.intensity); });
    case Property::light_color: return on_light([](const auto& l) { return l.color; });
    case Property::light_position: return scene.spot_lights[t.index].position;
    case Property::light_direction:
        if (t.light == LightKind::directional) return scene.directional_lights[t.index].direction;
        return scene.spot_lights[t.index].axis;
    case Property::light_max_angle: return dvec3(scene.spot_lights[t.index].max_angle);
    // In a group, a sphere's or plane's values are in the group's space.
    case Property::sphere_center: return (s->group < 0 ? scene.spheres()[s->index] : s->local_sphere).center;
    case Property::sphere_radius: return dvec3((s->group < 0 ? scene.spheres()[s->index] : s->local_sphere).radius);
    case Property::plane_normal: return (s->group < 0 ? scene.planes[s->index] : s->local_plane).normal;
    case Property::plane_distance: return dvec3((s->group < 0 ? scene.planes[s->index] : s->local_plane).distance);
    case Property::transform_translate: return s->transform.translate;
    case Property::transform_scale: return s->transform.scale;
    case Property::transform_axis: return s->transform.axis;
    case Property::transform_degrees: return dvec3(s->transform.radians * 180 / 3.14159265358979323846);
    case Property::transform_radians: return dvec3(s->transform.radians);
    case Property::material_color:
    case Property::material_diffuse_color: return m->diffuse_color;
    case Property::material_ambient_color: return m->ambient_color;
    case Property::material_specular_color: return m->specular_color;
    case Property::material_ambient: return dvec3(m->ambient);
    case Property::material_diffuse: return dvec3(m->diffuse);
    case Property::material_specular: return dvec3(m->specular);
    case Property::material_phong_exponent: return dvec3(m->phong_exponent);
    case Property::material_reflectivity: return dvec3(m->reflectivity);
    }
    return dvec3(0);
}

void set_value(const Target& t, const dvec3& v, Scene& scene, Camera& camera) {
    auto on_light = [&](auto&& write) {
        if (t.light == LightKind::ambient) write(scene.ambient_lights[t.index]);
        else if (t.light == LightKind::directional) write(scene.directional_lights[t.index]);
        else write(scene.spot_lights[t.index]);
    };
    Material<double>* m = t.index < scene.materials.size() ? &scene.materials[t.index] : nullptr;
    NamedSurface* s = t.index < scene.named_surfaces.size() ? &scene.named_surfaces[t.index] : nullptr;
    // In a group: the group's-space value, which place_groups carries to the world.
    auto sphere = [&]() -> Sphere<double>& { return s->group < 0 ? scene.spheres()[s->index] : s->local_sphere; };
    auto plane = [&]() -> Plane<double>& { return s->group < 0 ? scene.planes[s->index] : s->local_plane; };
    switch (t.property) {
    case Property::camera_view_point: camera.view_point = v; break;
    case Property::camera_look_at: camera.look_at = v; break;
    case Property::camera_up: camera.up = v; break;
    case Property::camera_projection_distance: camera.projection_distance = v.x; break;
    case Property::light_on: on_light([&](auto& l) { l.on = v.x != 0; }); break;
    case Property::light_intensity: on_light([&](auto& l) { l.intensity = v.x; }); break;
    case Property::light_color: on_light([&](auto& l) { l.color = v; }); break;
    case Property::light_position: scene.spot_lights[t.index].position = v; break;
    case Property::light_direction:
        if (t.light == LightKind::directional) scene.directional_lights[t.index].direction = unit_or_zero(v);
        else scene.spot_lights[t.index].axis = unit_or_zero(v);
        break;
    case Property::light_max_angle: scene.spot_lights[t.index].max_angle = v.x; break;
    case Property::sphere_center: sphere().center = v; break;
    case Property::sphere_radius: sphere().radius = v.x; break;
    case Property::plane_normal: plane().normal = unit_or_zero(v); break;
    case Property::plane_distance: plane().distance = v.x; break;
    case Property::material_color: m->ambient_color = m->diffuse_color = m->specular_color = v; break;
    case Property::material_ambient_color: m->ambient_color = v; break;
    case Property::material_diffuse_color: m->diffuse_color = v; break;
    case Property::material_specular_color: m->specular_color = v; break;
    case Property::material_ambient: m->ambient = v.x; break;
    case Property::material_diffuse: m->diffuse = v.x; break;
    case Property::material_specular: m->specular = v.x; break;
    case Property::material_phong_exponent: m->phong_exponent = v.x; break;
    case Property::material_reflectivity: m->reflectivity = v.x; break;
    default: break;  // a transform's parts: placed together by the movie
    }
}

std::string check_value(const Target& t, const dvec3& v) {
    if (!is_finite(v)) return "it must be finite";
    switch (t.kind) {
    case ValueKind::positive: return v.x > 0 ? "" : "it must be > 0";
    case ValueKind::non_negative: return v.x >= 0 ? "" : "it must be >= 0";
    case ValueKind::strength:
        return v.x < 0 ? "it must be >= 0" : v.x > Limits::max_strength ? "it must be at most 1e12" : "";
    case ValueKind::radius:
        return !(v.x > 0) ? "it must be > 0" : v.x > Limits::max_radius ? "it must be at most 1e12" : "";
    case ValueKind::unit_interval: return v.x >= 0 && v.x <= 1 ? "" : "it must be in 0..1";
    case ValueKind::direction: return max_abs_component(v) > 0 ? "" : "a direction must not be zero";
    case ValueKind::color: return v.x >= 0 && v.y >= 0 && v.z >= 0 ? "" : "a colour must be >= 0";
    case ValueKind::scale: {
        if (v.x == 0 || v.y == 0 || v.z == 0) return "a scale must not be 0";
        // What a scene's transform may scale by (scene/instance.h).
        const bool inside = within_scale_limits(v.x) && within_scale_limits(v.y) && within_scale_limits(v.z);
        return inside ? "" : "a scale must be 1e-12 to 1e12 in size";
    }
    default: return "";
    }
}

}  // namespace fh
