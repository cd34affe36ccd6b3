// Shared pieces of the robustness battery: the two scalar types,
// small scenes built in code, rendering with either precision, and the
// "no non-finite sample" check every rendered scene goes through (item 11).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>

#include "render/render.h"
#include "scene/scene.h"
#include "sanitizer_build.h"  // kSanitized: the slowest loops of the battery take fewer rays

namespace fh::robust {

using Scalars = ::testing::Types<float, double>;

template <typename T>
constexpr Precision precision_of() {
    return std::is_same_v<T, float> ? Precision::float32 : Precision::float64;
}

// A material with one colour for its three terms.
inline Material<double> material(dvec3 color, double ambient, double diffuse, double specular,
                                 double phong, bool glazed = false, double reflectivity = 0) {
    Material<double> m;
    m.ambient_color = m.diffuse_color = m.specular_color = color;
    m.ambient = ambient;
    m.diffuse = diffuse;
    m.specular = specular;
    m.phong_exponent = phong;
    m.glazed = glazed;
    m.reflectivity = reflectivity;
    return m;
}

inline int add_material(Scene& s, const std::string& name, const Material<double>& m) {
    s.material_names.push_back(name);
    s.materials.push_back(m);
    return int(s.materials.size()) - 1;
}

inline Effects all_effects() { return Effects{}; }

inline Effects effects(bool shadows, bool glazing) {
    Effects e;
    e.shadows = shadows;
    e.glazing = glazing;
    return e;
}

// One frame on the calling thread.
inline FrameResult render(const Scene& s, const Camera& c, Precision p, const Effects& fx,
                          int max_depth = 5) {
    RenderSettings rs;
    rs.precision = p;
    rs.max_depth = max_depth;
    rs.samples_per_pixel = 1;
    rs.effects = fx;
    return render_frame(s, c, rs, nullptr);
}

// Item 11: no NaN or infinity reached a pixel.
inline void expect_finite_frame(const FrameResult& r, const std::string& what) {
    EXPECT_EQ(r.counts.nonfinite_samples, 0u) << what;
}

inline int count_differing_pixels(const Image& a, const Image& b, int tolerance = 0) {
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])) > tolerance) {
                    ++n;
                    break;
                }
    return n;
}

inline Camera camera(Projection p, dvec3 view_point, dvec3 look_at, dvec3 up, int size,
                     double projection_distance = 10) {
    Camera c;
    c.projection = p;
    c.width = c.height = size;
    c.view_point = view_point;
    c.look_at = look_at;
    c.up = up;
    c.projection_distance = projection_distance;
    return c;
}

// A random unit vector (uniform on the sphere).
inline dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0, 1);
    for (;;) {
        const dvec3 v(n(rng), n(rng), n(rng));
        const double l = glm::length(v);
        if (l > 1e-3) return v / l;
    }
}

// A unit vector perpendicular to the unit vector u.
inline dvec3 random_perpendicular(std::mt19937_64& rng, const dvec3& u) {
    for (;;) {
        const dvec3 v = glm::cross(u, random_unit(rng));
        const double l = glm::length(v);
        if (l > 1e-3) return v / l;
    }
}

}  // namespace fh::robust
