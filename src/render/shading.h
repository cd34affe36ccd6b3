// Shading (report 8, SPEC section 4): the colour each ray of a batch brings back.
//   1. nearest hit; none -> the background
//   2. ambient
//   3-5. per directional or spot light, unless a shadow ray finds a blocker:
//        Lambert diffuse and Blinn-Phong specular (specular only where n.l > 0)
//   6. glazing: + reflectivity * colour of the mirrored ray, lit or not,
//      up to max_depth reflection rays in a chain.
// Colours stay unclamped here; the pixel clamps (render/render.cpp).
//
// The work goes in waves: the batch's nearest hits, then per light one batch
// of shadow rays for the hits that face it, then one batch of reflection rays
// for the glazed hits, which is the next wave. Glazing adds reflectivity times
// the next colour, so the report's recursion becomes a running weight per ray.
// F (ShaderFeature bits) fixes at compile time whether shadow rays, the
// specular term and glazing exist at all; with_shader picks the variant the
// frame's effect plan calls for.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/offset.h"
#include "render/background.h"
#include "render/batch_intersect.h"
#include "render/stats.h"

namespace fh {

// x^n for a whole n >= 0 by squaring: the report's Phong exponents are whole,
// and this is several times cheaper than std::pow.
template <typename T>
inline T pow_whole(T x, unsigned n) {
    T r = 1;
    while (n) {
        if (n & 1u) r *= x;
        x *= x;
        n >>= 1;
    }
    return r;
}

template <typename T, unsigned F>
class Shader {
public:
    static constexpr bool kShadowRays = (F & kShadows) != 0;
    static constexpr bool kSpecularTerm = (F & kSpecular) != 0;
    static constexpr bool kReflections = (F & kGlazing) != 0;
    static constexpr int N = RayBatch<T>::kCapacity;

    explicit Shader(const FlatScene<T>& scene) : scene_(scene) {}

    // colours[i] = the colour of camera ray i (unclamped). The batch is used
    // as the first wave and is left holding the last one.
    void trace(RayBatch<T>& camera_rays, Color<T>* colours, RayCounts& counts) const {
        Wave w(camera_rays);
        for (int i = 0; i < w.rays.size; ++i) {
            w.slot[i] = i;
            w.weight[i] = 1;
            colours[i] = Color<T>(0);
        }
        for (int depth = 0; w.rays.size > 0; ++depth) {
            shade_wave(w, colours, counts);
            if constexpr (!kReflections) break;
            if (depth >= scene_.plan.max_depth) break;
            reflect_wave(w);
            counts.reflection += std::uint64_t(w.rays.size);
        }
    }

    // One ray on its own (tests, debugging): the same path with a batch of one.
    Color<T> trace(const Ray<T>& ray, RayCounts& counts) const {
        RayBatch<T> b;
        b.push(ray);
        Color<T> c;
        trace(b, &c, counts);
        return c;
    }

private:
    // The rays in flight, and for each the camera ray it adds to and its weight.
    // Scratch of tens of kilobytes: constructed without zeroing it.
    struct Wave {
        explicit Wave(RayBatch<T>& r) : rays(r) {}
        RayBatch<T>& rays;
        int slot[N];
        T weight[N];
        // Filled by shade_wave: the surface points the rays hit.
        int hits = 0;
        SurfacePoint<T> point[N];
        Vec3<T> view[N];  // toward the viewer
        int hit_slot[N];
        T hit_weight[N];
    };

    void shade_wave(Wave& w, Color<T>* colours, RayCounts& counts) const {
        T t[N];
        std::int32_t prim[N];
        closest_hits(scene_, w.rays, t, prim);
        Color<T> local[N];
        w.hits = 0;
        for (int i = 0; i < w.rays.size; ++i) {
            const Ray<T> ray = w.rays.ray(i);
            if (prim[i] == kNoHit) {
                colours[w.slot[i]] += w.weight[i] * background(ray.direction);
                continue;
            }
            const int k = w.hits++;
            w.point[k] = scene_.surface(ray, scene_.hit_of(t[i], prim[i]));
            w.view[k] = -ray.direction;
            w.hit_slot[k] = w.slot[i];
            w.hit_weight[k] = w.weight[i];
            local[k] = scene_.ambient_terms[w.point[k].material];
        }
        for (size_t l = 0; l < scene_.directional_lights.size(); ++l)
            add_directional(w, l, local, counts);
        for (size_t l = 0; l < scene_.spot_lights.size(); ++l) add_spot(w, l, local, counts);
        for (int k = 0; k < w.hits; ++k) colours[w.hit_slot[k]] += w.hit_weight[k] * local[k];
    }

    // The hits facing the light, as a batch of shadow rays; blocked[j] for each.
    struct Lit {
        RayBatch<T> shadow;
        int hit[N];
        Vec3<T> to_light[N];
        T n_dot_l[N];
        T intensity[N];
        BlockMask<T> blocked[N];
    };

    void cast_shadows(Lit& lit, RayCounts& counts) const {
        if constexpr (kShadowRays) {
            find_blocked(scene_, lit.shadow, lit.blocked);
            counts.shadow += std::uint64_t(lit.shadow.size);
        } else {
            for (int j = 0; j < lit.shadow.size; ++j) lit.blocked[j] = 0;
        }
    }

    void add_directional(const Wave& w, size_t l, Color<T>* local, RayCounts& counts) const {
        const Vec3<T> to_light = scene_.directional_lights[l].to_light();
        Lit lit;
        for (int k = 0; k < w.hits; ++k) {
            const SurfacePoint<T>& sp = w.point[k];
            const T n_dot_l = glm::dot(sp.normal, to_light);
            if (n_dot_l <= T(0)) continue;  // faces away: no diffuse, no specular
            const int j = lit.shadow.size;
            lit.hit[j] = k;
            lit.to_light[j] = to_light;
            lit.n_dot_l[j] = n_dot_l;
            lit.intensity[j] = T(1);
            lit.shadow.push({offset_origin(sp.point, sp.normal), to_light});
        }
        cast_shadows(lit, counts);
        add_unblocked(w, lit, &scene_.directional_terms[l * scene_.materials.size()], local);
    }

    void add_spot(const Wave& w, size_t l, Color<T>* local, RayCounts& counts) const {
        const SpotLight<T>& spot = scene_.spot_lights[l];
        Lit lit;
        for (int k = 0; k < w.hits; ++k) {
            const SurfacePoint<T>& sp = w.point[k];
            const SpotRadiance<T> r = spot.radiance_at(sp.point);
            if (r.intensity <= T(0)) continue;
            const T n_dot_l = glm::dot(sp.normal, r.to_light);
            if (n_dot_l <= T(0)) continue;
            const int j = lit.shadow.size;
            lit.hit[j] = k;
            lit.n_dot_l[j] = n_dot_l;
            lit.intensity[j] = r.intensity;
            lit.to_light[j] = r.to_light;
            // Blockers count only between the point and the light.
            lit.shadow.push({offset_origin(sp.point, sp.normal), r.to_light}, r.distance);
        }
        cast_shadows(lit, counts);
        add_unblocked(w, lit, &scene_.spot_terms[l * scene_.materials.size()], local);
    }

    // Diffuse and specular of one light at the hits its shadow rays reached.
    // terms: the light's row of colour products, indexed by material.
    void add_unblocked(const Wave& w, const Lit& lit, const LightTerms<T>* terms,
                       Color<T>* local) const {
        for (int j = 0; j < lit.shadow.size; ++j) {
            if (lit.blocked[j]) continue;
            const int k = lit.hit[j];
            const SurfacePoint<T>& sp = w.point[k];
            local[k] += direct(terms[sp.material], sp, lit.to_light[j], w.view[k], lit.n_dot_l[j],
                               lit.intensity[j]);
        }
    }

    // Lambert + Blinn-Phong for one unshadowed light with n.l > 0.
    Color<T> direct(const LightTerms<T>& terms, const SurfacePoint<T>& sp, const Vec3<T>& to_light,
                    const Vec3<T>& view, T n_dot_l, T intensity) const {
        Color<T> c = n_dot_l * terms.diffuse;
        if constexpr (kSpecularTerm) {
            const Material<T>& m = scene_.materials[size_t(sp.material)];
            const Vec3<T> h = glm::normalize(to_light + view);
            const T n_dot_h = std::max(T(0), glm::dot(sp.normal, h));
            const T s = m.phong_whole >= 0 ? pow_whole(n_dot_h, unsigned(m.phong_whole))
                                           : std::pow(n_dot_h, m.phong_exponent);
            c += s * terms.specular;
        }
        return intensity * c;
    }

    // The glazed hits' mirrored rays become the next wave.
    void reflect_wave(Wave& w) const {
        w.rays.size = 0;
        for (int k = 0; k < w.hits; ++k) {
            const SurfacePoint<T>& sp = w.point[k];
            const Material<T>& m = scene_.materials[size_t(sp.material)];
            if (!m.glazed) continue;
            w.slot[w.rays.size] = w.hit_slot[k];
            w.weight[w.rays.size] = w.hit_weight[k] * m.reflectivity;
            w.rays.push({offset_origin(sp.point, sp.normal), reflect(-w.view[k], sp.normal)});
        }
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
