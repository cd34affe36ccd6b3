// Shading (report 8, SPEC section 4): the colour one ray brings back.
//   1. nearest hit; none -> the background
//   2. ambient
//   3-5. per directional or spot light, unless a shadow ray finds a blocker:
//        Lambert diffuse and Blinn-Phong specular (specular only where n.l > 0)
//   6. glazing: + reflectivity * colour of the mirrored ray, lit or not,
//      up to max_depth reflection rays in a chain.
// Colours stay unclamped here; the pixel clamps (render/render.cpp).
// Glazing adds reflectivity times the next colour, so the recursion of the
// report is a loop with a running weight.
// F (ShaderFeature bits) fixes at compile time whether shadow rays, the
// specular term and glazing exist at all; with_shader picks the variant the
// frame's effect plan calls for.
#pragma once

#include <cmath>

#include "core/offset.h"
#include "render/background.h"
#include "render/flat_scene.h"
#include "render/stats.h"

namespace fh {

template <typename T, unsigned F>
class Shader {
public:
    static constexpr bool kShadowRays = (F & kShadows) != 0;
    static constexpr bool kSpecularTerm = (F & kSpecular) != 0;
    static constexpr bool kReflections = (F & kGlazing) != 0;

    explicit Shader(const FlatScene<T>& scene) : scene_(scene) {}

    Color<T> trace(Ray<T> ray, RayCounts& counts) const {
        Color<T> total(0);
        T weight = 1;
        for (int depth = 0;; ++depth) {
            const Hit<T> hit = scene_.closest(ray);
            if (!hit.found()) return total + weight * background(ray.direction);
            const SurfacePoint<T> sp = scene_.surface(ray, hit);
            total += weight * shade_point(sp, -ray.direction, counts);
            if constexpr (!kReflections) return total;
            const Material<T>& m = scene_.materials[sp.material];
            if (!m.glazed || depth >= scene_.plan.max_depth) return total;
            weight *= m.reflectivity;
            ray = {offset_origin(sp.point, sp.normal), reflect(ray.direction, sp.normal)};
            ++counts.reflection;
        }
    }

    // Ambient plus every light's diffuse and specular at one point.
    Color<T> shade_point(const SurfacePoint<T>& sp, const Vec3<T>& view, RayCounts& counts) const {
        const size_t nm = scene_.materials.size();
        const Material<T>& m = scene_.materials[sp.material];
        Color<T> c = scene_.ambient_terms[sp.material];
        const Vec3<T> shadow_origin = offset_origin(sp.point, sp.normal);
        for (size_t l = 0; l < scene_.directional_lights.size(); ++l) {
            const Vec3<T> to_light = scene_.directional_lights[l].to_light();
            const T n_dot_l = glm::dot(sp.normal, to_light);
            if (n_dot_l <= T(0)) continue;  // faces away: no diffuse, no specular
            if constexpr (kShadowRays) {
                ++counts.shadow;
                if (scene_.occluded({shadow_origin, to_light}, kInfinity<T>)) continue;
            }
            c += direct(scene_.directional_terms[l * nm + sp.material], m, sp.normal, to_light,
                        view, n_dot_l, T(1));
        }
        for (size_t l = 0; l < scene_.spot_lights.size(); ++l) {
            const SpotRadiance<T> r = scene_.spot_lights[l].radiance_at(sp.point);
            if (r.intensity <= T(0)) continue;
            const T n_dot_l = glm::dot(sp.normal, r.to_light);
            if (n_dot_l <= T(0)) continue;
            if constexpr (kShadowRays) {
                ++counts.shadow;
                // Blockers count only between the point and the light.
                if (scene_.occluded({shadow_origin, r.to_light}, r.distance)) continue;
            }
            c += direct(scene_.spot_terms[l * nm + sp.material], m, sp.normal, r.to_light, view,
                        n_dot_l, r.intensity);
        }
        return c;
    }

private:
    // Lambert + Blinn-Phong for one unshadowed light with n.l > 0.
    Color<T> direct(const LightTerms<T>& terms, const Material<T>& m, const Vec3<T>& n,
                    const Vec3<T>& to_light, const Vec3<T>& view, T n_dot_l, T intensity) const {
        Color<T> c = n_dot_l * terms.diffuse;
        if constexpr (kSpecularTerm) {
            const Vec3<T> h = glm::normalize(to_light + view);
            const T n_dot_h = std::max(T(0), glm::dot(n, h));
            c += std::pow(n_dot_h, m.phong_exponent) * terms.specular;
        }
        return intensity * c;
    }

    static Vec3<T> reflect(const Vec3<T>& d, const Vec3<T>& n) {
        return glm::normalize(d - T(2) * glm::dot(d, n) * n);
    }

    const FlatScene<T>& scene_;
};

// Calls fn(shader) with the shader variant for the scene's effect plan.
template <typename T, typename Fn>
decltype(auto) with_shader(const FlatScene<T>& scene, Fn&& fn) {
    switch (shader_features(scene.plan)) {
    case 0: return fn(Shader<T, 0>(scene));
    case 1: return fn(Shader<T, 1>(scene));
    case 2: return fn(Shader<T, 2>(scene));
    case 3: return fn(Shader<T, 3>(scene));
    case 4: return fn(Shader<T, 4>(scene));
    case 5: return fn(Shader<T, 5>(scene));
    case 6: return fn(Shader<T, 6>(scene));
    default: return fn(Shader<T, 7>(scene));
    }
}

}  // namespace fh
