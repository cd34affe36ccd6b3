// Shading (report 8, SPEC section 4): the colour each ray of a packet brings back.
//   1. nearest hit; none -> the background
//   2. ambient
//   3-5. per directional or spot light, unless a shadow ray finds a blocker:
//        Lambert diffuse and Blinn-Phong specular (specular only where n.l > 0)
//   6. glazing: + reflectivity * colour of the mirrored ray, lit or not,
//      up to max_depth reflection rays in a chain.
//   (glTF's BLEND, instances only: a see-through hit's colour counts by its
//   opacity a, the ray going on past it by 1 - a: go_on.)
// Colours stay unclamped here; the pixel clamps (render/tile_renderer.h).
//
// A packet of rays goes through these steps together, each step one SIMD
// formula over its lanes, with a mask of the rays still in play: the shadow
// rays of the lit points, the reflection rays of the glazed hits. A step
// that no lane needs is skipped. Glazing adds reflectivity times the next
// colour, so the report's recursion becomes a loop with a running weight.
//
// What a hit's primitive and material contribute (centre, normal, colour
// terms) is the same for every lane that hit that primitive: it is looked up
// once per primitive a packet sees -- mostly one or two -- and blended into
// the lanes that hit it.
//
// A textured material (glTF's base colour texture: only instances have one)
// multiplies its ambient and diffuse colours by the texel colour at each
// hit (SurfaceLanes::albedo), and its normal texture turns the shading
// normal (render/normal_map.h); scenes without textures never read them.
//
// F (ShaderFeature bits) fixes at compile time whether shadow rays, the
// specular term and glazing exist at all; with_shader picks the variant the
// frame's effect plan calls for. kInstances: the scene has instances (the
// second level, render/instance_walk.h), reached through calls, so that
// every other scene's shader keeps its walks inlined and no call in its
// loop -- a call there, even one never taken, made the report's Movie 2
// 5-11% slower with AVX-512, whose vector registers a call may overwrite.
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "core/fast_math.h"
#include "core/offset.h"
#include "render/background.h"
#include "render/flat_scene.h"
#include "render/instance_walk.h"
#include "render/metal_rough.h"
#include "render/normal_map.h"
#include "render/stats.h"
#include "render/texture_footprint.h"

namespace fh {

template <typename T, unsigned F, bool kInstances = false>
class Shader {
public:
    static constexpr bool kShadowRays = (F & kShadows) != 0;
    static constexpr bool kSpecularTerm = (F & kSpecular) != 0;
    static constexpr bool kReflections = (F & kGlazing) != 0;

    // cone: the camera rays' (render/texture_footprint.h), for textures
    // read from their mipmaps; none: every texture read as magnified.
    explicit Shader(const FlatScene<T>& scene, PixelCone<T> cone = {})
        : scene_(scene), geometry_(*scene.geometry), cone_(cone) {
        if constexpr (kInstances) instances_ = scene.instances.get();
    }

    // The colour of each active ray of a packet (unclamped); 0 in the others.
    // first_hits: the primitives the rays' first hits can be on (a tile's
    // camera rays); nullptr: any.
    ColorLanes<T> trace(RayPacket<T> ray, LaneInts<T> active, RayCounts& counts,
                        const PrimitiveSubset* first_hits = nullptr) const {
        const Lanes<T> zero = splat(T(0));
        const ColorLanes<T> black{zero, zero, zero};
        ColorLanes<T> colour = black;
        Lanes<T> weight = splat(T(1));
        LaneInts<T> layers{};  // see-through surfaces each ray has gone through (go_on)
        Lanes<T> travelled = zero;  // each ray's path before its origin (its cone's distance)
        // Camera rays: their share of the cone (render/texture_footprint.h;
        // textures lie on instances' meshes only).
        Lanes<T> cone_share = splat(T(1));
        if constexpr (kInstances)
            if (scene_.minified) cone_share = cone_.share(ray.direction);
        for (int depth = 0;; ++depth) {
            LaneInts<T> instance;  // each lane's instance, or kNoInstance (kInstances only)
            const HitLanes<T> h = hits(ray, active, depth == 0 ? first_hits : nullptr, instance);
            const LaneInts<T> hit = h.prim != kNoHit;
            ColorLanes<T> local = select(active & ~hit, background(ray.direction), black);
            if (none(hit)) {
                colour += weight * local;
                break;
            }
            SurfaceLanes surface;
            if constexpr (kInstances) {
                instanced_surfaces(ray, h, instance, hit, travelled, cone_share, surface, local);
                if (scene_.minified) travelled += select(hit, h.t, zero);
            } else {
                surfaces(ray, h, hit, surface, local);
            }
            add_lights(ray, surface, hit, local, counts);
            if constexpr (kInstances) {
                if (scene_.blended) {
                    if (!go_on(ray, active, weight, colour, local, surface, hit, depth, layers, counts)) break;
                    continue;
                }
            }
            colour += weight * local;
            if constexpr (!kReflections) break;
            if (depth >= scene_.plan.max_depth) break;
            active = hit & surface.glazed;
            if (none(active)) break;
            counts.reflection += std::uint64_t(count(active));
            weight *= surface.reflectivity;
            // Unit to rounding, as the direction and the normal are: no normalize needed.
            const Vec3Lanes<T>& d = ray.direction;
            ray = {surface.origin, d - (T(2) * dot(d, surface.normal)) * surface.normal};
        }
        return colour;
    }

    // The same shader with another cone (an adaptive frame's refined pixels).
    Shader with_cone(PixelCone<T> cone) const {
        Shader s = *this;
        s.cone_ = cone;
        return s;
    }

    // One ray on its own (tests, debugging): a packet of one.
    Color<T> trace(const Ray<T>& ray, RayCounts& counts) const {
        return trace(RayPacket<T>::splat(ray), first_lanes<T>(1), counts).lane(0);
    }

private:
    // What each lane's hit looks like, as the lights and the reflection need
    // it. Lanes without a hit hold some primitive's values: a finite
    // reflectivity and material, no glazed bit, but a point and normal that
    // may be NaN (a ray from a sphere's centre) -- only steps masked by `hit`
    // or `lit` read those.
    struct SurfaceLanes {
        Vec3Lanes<T> point, normal;  // normal: unit, facing the ray
        Vec3Lanes<T> origin;         // where secondary rays start
        Lanes<T> reflectivity;
        LaneInts<T> glazed;
        LaneInts<T> material;
        ColorLanes<T> albedo;  // a textured scene's texel colours (1: none); else unused
        // A scene with see-through surfaces (FlatScene::blended): each hit's
        // opacity (1: opaque), and where a ray going on past it starts.
        Lanes<T> opacity;
        Vec3Lanes<T> beyond;
        // A scene with metallic-roughness textures (FlatScene::metal_rough):
        // each hit's metalness and roughness, read for those materials only.
        Lanes<T> metal, rough;
    };

    // A see-through ray goes on past this many surfaces at most; the last
    // counts as opaque (a bound on one ray's work, as kMaxCutoutLayers).
    static constexpr int kMaxSeeThroughLayers = 64;

    // In a scene with see-through surfaces (glTF's BLEND): each hit's own
    // colour counts by its opacity a, and a ray whose surface lets light
    // through (a < 1) goes on straight past it with weight (1 - a); a
    // glazed, opaque surface sends its reflection ray as in trace. Each lane
    // does one or the other, so a chain stays a loop. Returns whether any
    // lane goes on.
    FH_HOT_INLINE bool go_on(RayPacket<T>& ray, LaneInts<T>& active, Lanes<T>& weight, ColorLanes<T>& colour,
                             const ColorLanes<T>& local, const SurfaceLanes& s, const LaneInts<T>& hit, int depth,
                             LaneInts<T>& layers, RayCounts& counts) const {
        using Int = typename LaneTypes<T>::Int;
        const Lanes<T> one = splat(T(1));
        const Lanes<T> opacity = select(hit & (layers < Int(kMaxSeeThroughLayers)), s.opacity, one);
        colour += (weight * opacity) * local;
        const LaneInts<T> through = hit & (opacity < T(1));
        LaneInts<T> mirrored{};
        // A lane's reflections so far: its steps less its layers.
        if constexpr (kReflections)
            mirrored = hit & s.glazed & ~through & ((LaneInts<T>{} + Int(depth)) - layers < Int(scene_.plan.max_depth));
        if (none(through | mirrored)) return false;
        counts.transmitted += std::uint64_t(count(through));
        counts.reflection += std::uint64_t(count(mirrored));
        weight = select(through, weight * (one - opacity), weight * s.reflectivity);
        const Vec3Lanes<T>& d = ray.direction;
        ray = {select(through, s.beyond, s.origin), select(through, d, d - (T(2) * dot(d, s.normal)) * s.normal)};
        layers = select(through, layers + Int(1), layers);
        active = through | mirrored;
        return true;
    }

    // Calls fn(id, lanes, first) for each distinct id among the lanes in
    // mask, with the lanes that hold it. first is std::true_type for the
    // first call, whose values may go into every lane, and std::false_type
    // for the others, which blend theirs in: a packet that sees one
    // primitive -- most do -- blends nothing.
    template <typename Fn>
    static FH_HOT_INLINE void for_each_distinct(const LaneInts<T>& ids, LaneInts<T> mask, Fn&& fn) {
        auto next = [&](auto first) FH_HOT_LAMBDA {
            int lane = 0;
            while (mask[lane] == 0) ++lane;
            const LaneInts<T> same = mask & (ids == ids[lane]);
            fn(int(ids[lane]), same, first);
            mask &= ~same;
        };
        if (none(mask)) return;
        next(std::true_type{});
        while (any(mask)) next(std::false_type{});
    }

    // dst = value in the lanes, or everywhere on the first call.
    template <typename First, typename V>
    static FH_HOT_INLINE void put(V& dst, const V& value, const LaneInts<T>& lanes, First) {
        if constexpr (First::value) dst = value;
        else dst = select(lanes, value, dst);
    }

    // Hit points, facing normals, secondary-ray origins, material terms; the
    // ambient term goes straight into local (lanes with a hit only).
    FH_HOT_INLINE void surfaces(const RayPacket<T>& ray, const HitLanes<T>& h,
                                const LaneInts<T>& hit, SurfaceLanes& s, ColorLanes<T>& local) const {
        const Lanes<T> zero = splat(T(0));
        const Vec3Lanes<T> p = ray.at(select(hit, h.t, zero));
        ColorLanes<T> ambient;
        Vec3Lanes<T> geometric;  // the face's normal: where secondary rays start
        for_each_distinct(h.prim, hit, [&](int prim, const LaneInts<T>& lanes, auto first) FH_HOT_LAMBDA {
            Vec3Lanes<T> point, normal, shading;
            geometry_.project(prim, p, point, normal, shading);
            const int material = geometry_.surfaces[size_t(prim)].material;
            put_hit(point, normal, shading, material, lanes, first, s, geometric, ambient);
            if (scene_.textured) untextured(lanes, first, s);
        });
        finish_surfaces(ray, hit, geometric, ambient, s, local);
    }

    // One primitive's point, normals and material terms into the lanes that
    // hit it (surfaces).
    template <typename First>
    FH_HOT_INLINE void put_hit(const Vec3Lanes<T>& point, const Vec3Lanes<T>& normal, const Vec3Lanes<T>& shading,
                               int material, const LaneInts<T>& lanes, First first, SurfaceLanes& s,
                               Vec3Lanes<T>& geometric, ColorLanes<T>& ambient) const {
        put(s.point, point, lanes, first);
        put(geometric, normal, lanes, first);
        put(s.normal, shading, lanes, first);
        const MaterialShading<T>& m = scene_.shading[size_t(material)];
        put(ambient, Vec3Lanes<T>::splat(m.ambient), lanes, first);
        put(s.reflectivity, splat(m.reflectivity), lanes, first);
        put(s.glazed, m.glazed ? lanes : LaneInts<T>{}, lanes, first);
        put(s.material, LaneInts<T>{} + material, lanes, first);
    }

    // The ambient term into local; both normals turned to face the ray, and
    // where secondary rays start (surfaces).
    FH_HOT_INLINE void finish_surfaces(const RayPacket<T>& ray, const LaneInts<T>& hit, const Vec3Lanes<T>& geometric,
                                       const ColorLanes<T>& ambient, SurfaceLanes& s, ColorLanes<T>& local) const {
        const Lanes<T> zero = splat(T(0));
        local += select(hit, ambient, Vec3Lanes<T>{zero, zero, zero});
        // Both normals turn with the face: a smooth normal stays on the
        // side of the face the ray came from.
        const LaneInts<T> flip = dot(geometric, ray.direction) > T(0);
        s.normal = select(flip, -s.normal, s.normal);
        s.origin = offset_origin(s.point, select(flip, -geometric, geometric));
        if constexpr (kInstances)
            if (scene_.blended) s.beyond = offset_origin(s.point, select(flip, geometric, -geometric));
    }

    // The nearest hits on both levels, or on the world's alone.
    FH_HOT_INLINE HitLanes<T> hits(const RayPacket<T>& ray, const LaneInts<T>& active,
                                   const PrimitiveSubset* subset, LaneInts<T>& instance) const {
        if constexpr (kInstances) return closest_hits_out_of_line(geometry_, instances_, ray, active, instance, subset);
        else return closest_hits(geometry_, ray, active, subset);
    }
    // Shadow rays blocked on both levels, or on the world's alone.
    FH_HOT_INLINE LaneInts<T> blocked(const Vec3Lanes<T>& origin, const Vec3Lanes<T>& to_light,
                                      const Lanes<T>& distance, const LaneInts<T>& lit) const {
        if constexpr (kInstances) return occluded_out_of_line(geometry_, instances_, {origin, to_light}, distance, lit);
        else return occluded(geometry_, {origin, to_light}, distance, lit);
    }

    // Whether shadow rays go through see-through surfaces (a scene with
    // instances, some of them BLEND): known at compile time to be false
    // for every other shader.
    FH_HOT_INLINE bool see_through() const {
        if constexpr (kInstances) return scene_.blended;
        else return false;
    }
    FH_HOT_INLINE const InstanceSet<T>* instances() const {
        if constexpr (kInstances) return instances_;
        else return nullptr;
    }

    // The same where instances exist: lanes are told apart by instance and
    // primitive; an instance's primitive is projected in its mesh's space and
    // carried back to the world (normals by the inverse transpose).
    FH_HOT_INLINE void instanced_surfaces(const RayPacket<T>& ray, const HitLanes<T>& h, const LaneInts<T>& instance,
                                          const LaneInts<T>& hit, const Lanes<T>& travelled,
                                          const Lanes<T>& cone_share, SurfaceLanes& s,
                                          ColorLanes<T>& local) const {
        const Lanes<T> zero = splat(T(0));
        const Vec3Lanes<T> p = ray.at(select(hit, h.t, zero));
        ColorLanes<T> ambient{zero, zero, zero};
        Vec3Lanes<T> geometric{zero, zero, zero};
        for_each_distinct_pair(instance, h.prim, hit, [&](int in, int prim, const LaneInts<T>& lanes, auto first)
                                                          FH_HOT_LAMBDA {
            Vec3Lanes<T> point, normal, shading;
            if (in < 0) {
                geometry_.project(prim, p, point, normal, shading);
                const int material = geometry_.surfaces[size_t(prim)].material;
                put_hit(point, normal, shading, material, lanes, first, s, geometric, ambient);
                if (scene_.textured) untextured(lanes, first, s);
                if (scene_.blended) put(s.opacity, splat(T(1)), lanes, first);
                if (scene_.metal_rough) {
                    // (A scene file may give a shape a glTF material: its factors.)
                    const MaterialShading<T>& m = scene_.shading[size_t(material)];
                    put_metal_rough(splat(m.metallic), splat(m.roughness), lanes, first, s);
                }
                return;
            }
            const FlatInstance<T>& inst = instances_->instances[size_t(in)];
            const FlatGeometry<T>& mesh = *instances_->meshes[size_t(inst.mesh)];
            mesh.project(prim, inst.to_object.point(p), point, normal, shading);
            const bool smooth = mesh.surfaces[size_t(prim)].smooth >= 0;
            // Where the hits lie on the triangle, for its textures and
            // vertex colours; a normal texture turns the shading normal in
            // the mesh's space.
            TrianglePoint<T> at{};
            if (scene_.textured && (!mesh.uvs.empty() || !mesh.colors.empty())) at = mesh.point_on(prim, point);
            if (scene_.minified && !mesh.uvs.empty())
                at.footprint = footprint_on(mesh, prim, inst, ray.direction,
                                            cone_.at(travelled + h.t) * cone_share, lanes);
            const MaterialShading<T>& m = scene_.shading[size_t(inst.material)];
            const bool bumpy = scene_.textured && m.normal_texture >= 0 && !mesh.uvs.empty();
            if (bumpy)
                shading = normal_mapped(mesh, prim, at, shading, scene_.textures[size_t(m.normal_texture)],
                                        m.normal_scale);
            const Vec3Lanes<T> object_point = point;
            point = inst.to_world.point(point);
            normal = normalize(inst.normal_to_world.vector(normal));
            shading = smooth || bumpy ? normalize(inst.normal_to_world.vector(shading)) : normal;
            put_hit(point, normal, shading, inst.material, lanes, first, s, geometric, ambient);
            if (scene_.textured) textured(mesh, prim, at, inst.material, lanes, first, s, ambient);
            if (scene_.metal_rough) {
                // Per hit where the material has the texture; its factors elsewhere (not read).
                if (m.metal_rough_texture >= 0 && !mesh.uvs.empty()) {
                    Lanes<T> metal, rough;
                    metal_rough_at<T>(scene_.textures[size_t(m.metal_rough_texture)], at, m.metallic, m.roughness,
                                      metal, rough);
                    put_metal_rough(metal, rough, lanes, first, s);
                    if constexpr (kReflections) {
                        const LaneInts<T> glazed = polished<T>(metal, rough);
                        put(s.glazed, glazed, lanes, first);
                        put(s.reflectivity, select(glazed, mirror_share<T>(metal, rough), splat(T(0))), lanes, first);
                    }
                } else {
                    put_metal_rough(splat(m.metallic), splat(m.roughness), lanes, first, s);
                }
            }
            if (scene_.blended) {
                const Cutout* cut = inst.cutout >= 0 ? &instances_->cutouts[size_t(inst.cutout)] : nullptr;
                put(s.opacity, cut && cut->blend ? alpha_at(mesh, *cut, prim, object_point) : splat(T(1)), lanes,
                    first);
            }
        });
        finish_surfaces(ray, hit, geometric, ambient, s, local);
    }

    // A textured material's texel colours at an instance's points (`at` on
    // triangle `prim` of its mesh), times the mesh's vertex colours where it
    // has them, into s.albedo, and its ambient term times them -- and times
    // its occlusion, plus its emissive colour times the emissive texel --
    // into ambient; none of these: albedo 1. One sample of each texture per
    // hit, no allocation.
    template <typename First>
    FH_HOT_INLINE void textured(const FlatGeometry<T>& mesh, int prim, const TrianglePoint<T>& at, int material,
                                const LaneInts<T>& lanes, First first, SurfaceLanes& s, ColorLanes<T>& ambient) const {
        const MaterialShading<T>& m = scene_.shading[size_t(material)];
        const bool uvs = !mesh.uvs.empty();
        const bool texel = m.texture >= 0 && uvs, glow = m.emissive_texture >= 0 && uvs,
                   occluded = m.occlusion_texture >= 0 && uvs;
        if (!texel && !glow && !occluded && mesh.colors.empty()) {
            untextured(lanes, first, s);
            return;
        }
        const Lanes<T> one = splat(T(1));
        ColorLanes<T> albedo{one, one, one};
        if (texel) {
            const TexelLanes<T> c = scene_.textures[size_t(m.texture)].template sample<T>(at.u, at.v, at.footprint);
            albedo = {c.r, c.g, c.b};
        }
        if (!mesh.colors.empty()) {
            const ColorLanes<T> c = mesh.color_at(prim, at.b1, at.b2);
            albedo = {albedo.x * c.x, albedo.y * c.y, albedo.z * c.z};
        }
        put(s.albedo, albedo, lanes, first);
        ColorLanes<T> tinted{albedo.x * m.tinted_ambient.x, albedo.y * m.tinted_ambient.y,
                             albedo.z * m.tinted_ambient.z};
        if (occluded) {
            const Lanes<T> r = scene_.textures[size_t(m.occlusion_texture)].template sample<T>(at.u, at.v, at.footprint).r;
            const Lanes<T> factor = T(1) + m.occlusion_strength * (r - T(1));
            tinted = {tinted.x * factor, tinted.y * factor, tinted.z * factor};
        }
        if (glow) {
            const TexelLanes<T> c = scene_.textures[size_t(m.emissive_texture)].template sample<T>(at.u, at.v, at.footprint);
            put(ambient, tinted + ColorLanes<T>{c.r * m.emissive.x, c.g * m.emissive.y, c.b * m.emissive.z}, lanes, first);
        } else {
            put(ambient, tinted + m.emissive, lanes, first);
        }
    }

    template <typename First>
    static FH_HOT_INLINE void put_metal_rough(const Lanes<T>& metal, const Lanes<T>& rough, const LaneInts<T>& lanes,
                                              First first, SurfaceLanes& s) {
        put(s.metal, metal, lanes, first);
        put(s.rough, rough, lanes, first);
    }

    // In a textured scene, a surface with neither texels nor vertex colours
    // (any of the world's, or an instance's mesh without them): albedo 1
    // (put_hit's ambient, emissive included, is already its own).
    template <typename First>
    FH_HOT_INLINE void untextured(const LaneInts<T>& lanes, First first, SurfaceLanes& s) const {
        put(s.albedo, ColorLanes<T>::splat(Color<T>(1)), lanes, first);
    }

    // Calls fn(a, b, lanes, first) for each distinct pair (a, b) among the
    // lanes in mask, as for_each_distinct does for one id.
    template <typename Fn>
    static FH_HOT_INLINE void for_each_distinct_pair(const LaneInts<T>& a, const LaneInts<T>& b, LaneInts<T> mask,
                                                     Fn&& fn) {
        auto next = [&](auto first) FH_HOT_LAMBDA {
            int lane = 0;
            while (mask[lane] == 0) ++lane;
            const LaneInts<T> same = mask & (a == a[lane]) & (b == b[lane]);
            fn(int(a[lane]), int(b[lane]), same, first);
            mask &= ~same;
        };
        if (none(mask)) return;
        next(std::true_type{});
        while (any(mask)) next(std::false_type{});
    }

    // Inlined into trace: once the BVH walk made occluded() large, GCC
    // stopped inlining this on its own, and the call (the surface's lanes
    // passed through memory) cost Movie 2 3% of its frame.
    FH_HOT_INLINE void add_lights(const RayPacket<T>& ray, const SurfaceLanes& s, const LaneInts<T>& hit,
                                  ColorLanes<T>& local, RayCounts& counts) const {
        const size_t materials = scene_.shading.size();
        for (size_t l = 0; l < scene_.directional_lights.size(); ++l) {
            const LightSample<T> sample{Vec3Lanes<T>::splat(scene_.directional_lights[l].to_light()),
                                        splat(kInfinity<T>), splat(T(1))};
            add_light(ray, s, hit, sample, &scene_.directional_terms[l * materials], local, counts);
        }
        for (size_t l = 0; l < scene_.spot_lights.size(); ++l)
            add_light(ray, s, hit, scene_.spot_lights[l].radiance_at(s.point, scene_.spot_cones[l]),
                      &scene_.spot_terms[l * materials], local, counts);
    }

    // Diffuse and specular of one light (report 8.2-8.3): the light's sample
    // at each point (direction, distance, intensity) and its colour products
    // with each material.
    FH_HOT_INLINE void add_light(const RayPacket<T>& ray, const SurfaceLanes& s, const LaneInts<T>& hit,
                                 const LightSample<T>& light, const LightTerms<T>* terms,
                                 ColorLanes<T>& local, RayCounts& counts) const {
        const Lanes<T> zero = splat(T(0));
        const Lanes<T> n_dot_l = dot(s.normal, light.to_light);
        // Faces away or gets nothing: no diffuse, no specular, no shadow ray.
        // (intensity >= 0, so one product tests both.)
        LaneInts<T> lit = hit & (light.intensity * n_dot_l > T(0));
        if (none(lit)) return;
        Lanes<T> intensity = light.intensity;
        if constexpr (kShadowRays) {
            counts.shadow += std::uint64_t(count(lit));
            if (see_through()) {
                // What see-through surfaces on the way let through dims the light.
                const Lanes<T> through = light_through_out_of_line(geometry_, instances(), {s.origin, light.to_light},
                                                                   light.distance, lit);
                lit &= through > T(0);
                intensity = intensity * through;
            } else {
                lit &= ~blocked(s.origin, light.to_light, light.distance, lit);
            }
            if (none(lit)) return;
        }
        // Per material the lit points show: its colour terms with this light,
        // its Phong exponent. (Unlit lanes: some material's, masked below.)
        ColorLanes<T> kd, ks;
        Lanes<T> exponent;
        LaneInts<T> whole_exponent;
        for_each_distinct(s.material, lit, [&](int m, const LaneInts<T>& lanes, auto first) FH_HOT_LAMBDA {
            if constexpr (kInstances)
                if (scene_.metal_rough && scene_.shading[size_t(m)].metal_rough_texture >= 0) {
                    // Strengths, tint and exponent per hit (render/metal_rough.h).
                    ColorLanes<T> hit_kd, hit_ks;
                    Lanes<T> hit_exponent;
                    metal_rough_terms<T>(s.metal, s.rough, terms[m].diffuse_unit, terms[m].tinted, terms[m].white,
                                         hit_kd, hit_ks, hit_exponent);
                    put(kd, hit_kd, lanes, first);
                    put(ks, hit_ks, lanes, first);
                    if constexpr (kSpecularTerm) {
                        put(exponent, hit_exponent, lanes, first);
                        put(whole_exponent, LaneInts<T>{}, lanes, first);
                    }
                    return;
                }
            put(kd, Vec3Lanes<T>::splat(terms[m].diffuse), lanes, first);
            put(ks, Vec3Lanes<T>::splat(terms[m].specular), lanes, first);
            if constexpr (kSpecularTerm) {
                const MaterialShading<T>& material = scene_.shading[size_t(m)];
                put(exponent, splat(material.exponent), lanes, first);
                put(whole_exponent, material.whole_exponent ? lanes : LaneInts<T>{}, lanes, first);
            }
        });
        if constexpr (kInstances)
            if (scene_.textured) kd = {kd.x * s.albedo.x, kd.y * s.albedo.y, kd.z * s.albedo.z};
        // A select, not a product with 0: an unlit lane may hold NaN.
        const Lanes<T> diffuse = select(lit, intensity * n_dot_l, zero);
        Lanes<T> specular = zero;
        if constexpr (kSpecularTerm) {
            // intensity (n.h)^exponent, h the half vector of the light and the viewer.
            const Vec3Lanes<T> h = normalize(light.to_light - ray.direction);
            const Lanes<T> n_dot_h = max(zero, dot(s.normal, h));
            // Square-and-multiply, one step per bit of the scene's largest
            // exponent (7 for the report's 100).
            Lanes<T> power = splat(T(1)), left = exponent;
            for (int bit = scene_.exponent_bits - 1; bit >= 0; --bit)
                pow_whole_step(power, n_dot_h, left, bit);
            if (scene_.fractional_exponents)  // rare: std::pow where needed
                for (int i = 0; i < kLanes<T>; ++i)
                    if (lit[i] && !whole_exponent[i]) power[i] = std::pow(n_dot_h[i], exponent[i]);
            specular = select(lit, intensity * power, zero);
        }
        local.x += diffuse * kd.x + specular * ks.x;
        local.y += diffuse * kd.y + specular * ks.y;
        local.z += diffuse * kd.z + specular * ks.z;
    }

    const FlatScene<T>& scene_;
    const FlatGeometry<T>& geometry_;
    // kInstances: the scene's instances. Else nothing at all: the shader of
    // scenes without instances is the same object as before they existed.
    struct NoInstances {};
    [[no_unique_address]] std::conditional_t<kInstances, const InstanceSet<T>*, NoInstances> instances_;
    PixelCone<T> cone_;
};

// Calls fn(shader) with the shader variant for the scene's effect plan and
// whether it has instances.
template <typename T, bool kInstances, typename Fn>
decltype(auto) with_shader_of(const FlatScene<T>& scene, Fn&& fn, PixelCone<T> cone) {
    switch (shader_features(scene.plan)) {
    case 0: return fn(Shader<T, 0, kInstances>(scene, cone));
    case 1: return fn(Shader<T, 1, kInstances>(scene, cone));
    case 2: return fn(Shader<T, 2, kInstances>(scene, cone));
    case 3: return fn(Shader<T, 3, kInstances>(scene, cone));
    case 4: return fn(Shader<T, 4, kInstances>(scene, cone));
    case 5: return fn(Shader<T, 5, kInstances>(scene, cone));
    case 6: return fn(Shader<T, 6, kInstances>(scene, cone));
    default: return fn(Shader<T, 7, kInstances>(scene, cone));
    }
}
// cone: the camera rays' (render/texture_footprint.h); none: textures
// read as magnified.
template <typename T, typename Fn>
decltype(auto) with_shader(const FlatScene<T>& scene, Fn&& fn, PixelCone<T> cone = {}) {
    if (scene.instances) return with_shader_of<T, true>(scene, fn, cone);
    return with_shader_of<T, false>(scene, fn, cone);
}

}  // namespace fh
