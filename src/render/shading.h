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
// of shadow rays for the hit points that face it, then one batch of
// reflection rays for the glazed hits, which is the next wave. Glazing adds
// reflectivity times the next colour, so the report's recursion becomes a
// running weight per ray.
//
// Every per-ray step is a branch-free loop over the wave in structure-of-
// arrays form, which GCC vectorises across AVX2 lanes: misses run through
// the same arithmetic as hits (with the no-hit row of FlatScene::rows) and
// are masked at the end. Only gathering the rays that go on -- shadow rays
// of lit points, reflection rays of glazed hits -- and adding each ray's
// colour to its camera ray are scalar loops, of a few stores per ray.
//
// F (ShaderFeature bits) fixes at compile time whether shadow rays, the
// specular term and glazing exist at all; with_shader picks the variant the
// frame's effect plan calls for.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/fast_math.h"
#include "core/offset.h"
#include "render/background.h"
#include "render/batch_intersect.h"
#include "render/stats.h"

namespace fh {

template <typename T, unsigned F>
class Shader {
public:
    static constexpr bool kShadowRays = (F & kShadows) != 0;
    static constexpr bool kSpecularTerm = (F & kSpecular) != 0;
    static constexpr bool kReflections = (F & kGlazing) != 0;
    static constexpr int N = RayBatch<T>::kCapacity;
    using Mask = BlockMask<T>;

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
    // The rays in flight and, for each, what its hit looks like. Scratch of
    // tens of kilobytes: constructed without zeroing it.
    struct Wave {
        explicit Wave(RayBatch<T>& batch) : rays(batch) {}
        RayBatch<T>& rays;
        int slot[N];  // the camera ray each adds to
        T weight[N];  // and with what weight
        std::int32_t row[N];  // FlatScene::rows index: primitive id + 1, 0 for a miss
        Mask hit[N];          // row != 0, as wide as T
        alignas(64) T px[N], py[N], pz[N];  // the hit point
        alignas(64) T nx[N], ny[N], nz[N];  // the normal, facing the ray
        alignas(64) T sx[N], sy[N], sz[N];  // where secondary rays start
        alignas(64) T exponent[N];          // Phong exponent of the hit's material
        alignas(64) T r[N], g[N], b[N];     // the colour the ray brings back
    };

    // Vectors of a wave's arrays, by ray.
    static FH_HOT_INLINE Vec3<T> at(const T* x, const T* y, const T* z, int i) {
        return {x[i], y[i], z[i]};
    }
    static FH_HOT_INLINE void put(T* x, T* y, T* z, int i, const Vec3<T>& v) {
        x[i] = v.x;
        y[i] = v.y;
        z[i] = v.z;
    }

    void shade_wave(Wave& w, Color<T>* colours, RayCounts& counts) const {
        find_surfaces(w);
        for (size_t l = 0; l < scene_.directional_lights.size(); ++l) {
            const Vec3<T> to_light = scene_.directional_lights[l].to_light();
            add_light(w, &scene_.directional_terms[l * scene_.rows.size()], counts,
                      [to_light](const Vec3<T>&) FH_HOT_LAMBDA {
                          return SpotRadiance<T>{to_light, kInfinity<T>, T(1)};
                      });
        }
        for (size_t l = 0; l < scene_.spot_lights.size(); ++l) {
            // A copy, not a reference: the loop over the wave keeps it in registers.
            add_light(w, &scene_.spot_terms[l * scene_.rows.size()], counts,
                      [spot = scene_.spot_lights[l],
                       widest = scene_.spot_lights[l].widest_angle()](const Vec3<T>& p)
                          FH_HOT_LAMBDA { return spot.radiance_at(p, widest); });
        }
        const int n = w.rays.size;
        for (int i = 0; i < n; ++i) {  // misses see the sky
            const Color<T> sky = background(Vec3<T>(w.rays.dx[i], w.rays.dy[i], w.rays.dz[i]));
            const bool hit = w.hit[i] != 0;
            w.r[i] = hit ? w.r[i] : sky.x;
            w.g[i] = hit ? w.g[i] : sky.y;
            w.b[i] = hit ? w.b[i] : sky.z;
        }
        for (int i = 0; i < n; ++i)
            colours[w.slot[i]] += w.weight[i] * Color<T>(w.r[i], w.g[i], w.b[i]);
    }

    // Hit points, facing normals, secondary-ray origins, ambient colour.
    void find_surfaces(Wave& w) const {
        T t[N];
        std::int32_t prim[N];
        closest_hits(scene_, w.rays, t, prim);
        const PrimitiveRow<T>* rows = scene_.rows.data();
        for (int i = 0; i < w.rays.size; ++i) {
            const std::int32_t row = prim[i] + 1;
            const PrimitiveRow<T>& pr = rows[row];
            // A miss (row 0) goes through the same arithmetic at t = 0.
            const SurfacePoint<T> sp = surface_at(pr, w.rays.ray(i), row != 0 ? t[i] : T(0));
            w.row[i] = row;
            w.hit[i] = row != 0;
            w.exponent[i] = pr.exponent;
            put(w.px, w.py, w.pz, i, sp.point);
            put(w.nx, w.ny, w.nz, i, sp.normal);
            put(w.sx, w.sy, w.sz, i, offset_origin(sp.point, sp.normal));
            put(w.r, w.g, w.b, i, pr.ambient.vec());
        }
    }

    // Diffuse and specular of one light (report 8.2-8.3). light_at(point)
    // gives the direction to the light, its distance and its intensity
    // there; terms: the light's colour products, by primitive row.
    template <typename LightAt>
    void add_light(Wave& w, const LightTerms<T>* terms, RayCounts& counts,
                   const LightAt light_at) const {
        const int n = w.rays.size;
        alignas(64) T lx[N], ly[N], lz[N], distance[N], intensity[N], n_dot_l[N];
        Mask lit[N];
        for (int i = 0; i < n; ++i) {
            const SpotRadiance<T> s = light_at(at(w.px, w.py, w.pz, i));
            const T ndl = glm::dot(at(w.nx, w.ny, w.nz, i), s.to_light);
            put(lx, ly, lz, i, s.to_light);
            distance[i] = s.distance;
            intensity[i] = s.intensity;
            n_dot_l[i] = ndl;
            // Faces away or gets nothing: no diffuse, no specular, no shadow
            // ray. (intensity >= 0, so one product tests both.)
            lit[i] = ((w.hit[i] != 0) & (s.intensity * ndl > T(0))) ? 1 : 0;
        }
        if constexpr (kShadowRays) cast_shadows(w, lx, ly, lz, distance, lit, counts);

        // The weights of the light's diffuse and specular colours at each
        // point: intensity n.l and intensity (n.h)^exponent, h the half vector.
        alignas(64) T diffuse[N], specular[N], n_dot_h[N], exponent[N];
        for (int i = 0; i < n; ++i) {
            // A select, not a product with 0: an unlit lane may hold NaN.
            diffuse[i] = lit[i] != 0 ? intensity[i] * n_dot_l[i] : T(0);
            specular[i] = 1;
            if constexpr (kSpecularTerm) {
                const Vec3<T> view(-w.rays.dx[i], -w.rays.dy[i], -w.rays.dz[i]);
                const Vec3<T> h = glm::normalize(at(lx, ly, lz, i) + view);
                n_dot_h[i] = std::max(T(0), glm::dot(at(w.nx, w.ny, w.nz, i), h));
                exponent[i] = w.exponent[i];
            }
        }
        if constexpr (kSpecularTerm) {
            // Square-and-multiply, one pass per bit of the scene's largest
            // exponent (7 for the report's 100) rather than 12 per point.
            for (int bit = scene_.exponent_bits - 1; bit >= 0; --bit)
                for (int i = 0; i < n; ++i) pow_whole_step(specular[i], n_dot_h[i], exponent[i], bit);
            if (scene_.fractional_exponents)  // rare: std::pow where needed
                for (int i = 0; i < n; ++i)
                    if (scene_.rows[size_t(w.row[i])].whole == T(0))
                        specular[i] = std::pow(n_dot_h[i], w.exponent[i]);
        }
        for (int i = 0; i < n; ++i)
            specular[i] = kSpecularTerm && lit[i] != 0 ? intensity[i] * specular[i] : T(0);
        for (int i = 0; i < n; ++i) {
            const LightTerms<T>& k = terms[w.row[i]];
            w.r[i] += diffuse[i] * k.diffuse.x + specular[i] * k.specular.x;
            w.g[i] += diffuse[i] * k.diffuse.y + specular[i] * k.specular.y;
            w.b[i] += diffuse[i] * k.diffuse.z + specular[i] * k.specular.z;
        }
    }

    // One shadow ray per lit point, toward the light and no farther; lit
    // is cleared where something blocks it.
    void cast_shadows(const Wave& w, const T* lx, const T* ly, const T* lz, const T* distance,
                      Mask* lit, RayCounts& counts) const {
        RayBatch<T> shadow;
        int from[N];
        int m = 0;
        for (int i = 0; i < w.rays.size; ++i) {  // written always, kept if lit
            shadow.set(m, {at(w.sx, w.sy, w.sz, i), at(lx, ly, lz, i)}, distance[i]);
            from[m] = i;
            m += int(lit[i]);
        }
        shadow.size = m;
        Mask blocked[N];
        find_blocked(scene_, shadow, blocked);
        for (int j = 0; j < m; ++j) lit[from[j]] = 1 - blocked[j];
        counts.shadow += std::uint64_t(m);
    }

    // The glazed hits' mirrored rays become the next wave.
    void reflect_wave(Wave& w) const {
        const int n = w.rays.size;
        alignas(64) T rx[N], ry[N], rz[N];
        for (int i = 0; i < n; ++i) {
            const Vec3<T> d(w.rays.dx[i], w.rays.dy[i], w.rays.dz[i]);
            const Vec3<T> normal = at(w.nx, w.ny, w.nz, i);
            // Unit to rounding, as d and the normal are: no normalize needed.
            put(rx, ry, rz, i, d - T(2) * glm::dot(d, normal) * normal);
        }
        int m = 0;
        for (int i = 0; i < n; ++i) {  // written always, kept if glazed; m <= i
            const PrimitiveRow<T>& pr = scene_.rows[size_t(w.row[i])];  // a miss: not glazed
            w.rays.set(m, {at(w.sx, w.sy, w.sz, i), at(rx, ry, rz, i)});
            w.slot[m] = w.slot[i];
            w.weight[m] = w.weight[i] * pr.reflectivity;
            m += int(pr.glazed != T(0));
        }
        w.rays.size = m;
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
