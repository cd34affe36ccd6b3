// What a movie can animate: one property of the camera or of a named light,
// surface or material, addressed by a path such as `lights.spot.intensity`.
// Every value travels as a dvec3 -- a number in x, a flag as 0 or 1 -- so
// one kind of path (anim/path.h) serves them all.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace fh {

enum class Property {
    camera_view_point, camera_look_at, camera_up, camera_projection_distance,
    light_on, light_intensity, light_color, light_position, light_direction, light_max_angle,
    sphere_center, sphere_radius, plane_normal, plane_distance,
    transform_translate, transform_scale, transform_axis, transform_degrees, transform_radians,
    material_color, material_ambient_color, material_diffuse_color, material_specular_color,
    material_ambient, material_diffuse, material_specular, material_phong_exponent, material_reflectivity,
};

// How a value is read and what it must be at every frame.
enum class ValueKind {
    number,        // any finite number
    positive,      // > 0
    non_negative,  // >= 0
    strength,      // 0 .. Limits::max_strength (an intensity; a material's ambient, diffuse, specular)
    radius,        // > 0, at most Limits::max_radius
    unit_interval, // 0 .. 1
    point,         // any finite vector
    direction,     // a non-zero vector
    color,         // each component >= 0 (0..255 in the file)
    scale,         // a number (all three axes) or a vector, each non-zero (negative: a mirror)
    flag,          // true or false: always a step
};

enum class LightKind { ambient, directional, spot };

// One animatable property of one thing.
struct Target {
    Property property = Property::camera_view_point;
    ValueKind kind = ValueKind::point;
    LightKind light = LightKind::ambient;  // light_*: which array `index` is in
    size_t index = 0;  // the light, material or named surface (Scene::named_surfaces)
    std::string path;  // as written, for messages: "lights.spot.intensity"
};

// What one kind of thing can animate, by the name after its own.
struct PropertyName {
    const char* name;
    Property property;
    ValueKind kind;
};
std::vector<PropertyName> camera_properties(Projection projection);
std::vector<PropertyName> light_properties(LightKind kind);
std::vector<PropertyName> surface_properties(SurfaceKind kind);
std::vector<PropertyName> material_properties();

// The value a target has in `scene` / `camera` (the file's, before a movie
// changes it).
dvec3 value_of(const Target& t, const Scene& scene, const Camera& camera);

// Sets the target's value. Directions of lights and planes are stored unit;
// a transform's parts are gathered by the caller (anim/movie.cpp), not set
// here.
void set_value(const Target& t, const dvec3& value, Scene& scene, Camera& camera);

// The reason `value` is not allowed for the target ("it must be > 0"), or
// empty when it is.
std::string check_value(const Target& t, const dvec3& value);

// A transform's parts.
inline bool is_transform(Property p) {
    return p >= Property::transform_translate && p <= Property::transform_radians;
}
// The camera, whose state camera_at computes alone.
inline bool is_camera(Property p) { return p <= Property::camera_projection_distance; }
// Moves geometry: the BVH is refitted for it.
inline bool moves_shapes(Property p) {
    return p >= Property::sphere_center && p <= Property::transform_radians;
}

}  // namespace fh
