// The Embree 3 peer of the mesh benchmarks (scripts/bench_scaling.sh): the
// scene family of bench/bench_scaling.cpp -- an icosphere of 20 * 4^k
// triangles (k = 1 .. 8) of radius 3 at the origin on the floor z = -3 -- and
// the Stanford bunny of animations/bunny.yaml (floor z = -2.2078), rendered by
// Embree 3 with the same camera, the same rays and the same shading as
// firsthit: 800 x 800, 1 sample at each pixel's centre, camera at (0, -12, 6)
// looking along (0, 12, -6), up (0, 0, 1), projection distance 10; Lambert +
// ambient + one directional light with shadows.
//
// How Embree is driven, the way its tutorials do for coherent rays:
// RTC_SCENE_FLAG_NONE, RTC_BUILD_QUALITY_MEDIUM (the default), one
// triangle-mesh geometry; the image cut into 16 x 16 tiles handed out to the
// threads (started once) by an atomic counter, each tile traced in packets
// of the widest size this CPU's Embree traces natively (16 rays in 4 x 4
// pixels with AVX-512, 8 in 4 x 2 with AVX2: rtcIntersect16/8), then one
// rtcOccluded16/8 for the lanes that face the light (--width forces 4, 8 or
// 16; a width wider than native Embree traces ray by ray); flush-to-zero
// and denormals-are-zero on in every tracing thread (Embree's
// recommendation). Colours are computed in float.
//
// The floor is handled analytically in the shading code, not as triangles in
// Embree: one ray-plane division per lane after rtcIntersect, and one for
// the shadow rays (which never hit it here: the light comes from above).
// That is what firsthit does too (planes are outside its BVH), and two huge
// triangles would only widen Embree's root boxes.
//
// Output: CSV on stdout, one row per scene
//   scene,triangles,build_ms,render_ms,rays_per_second
// build_ms: rtcCommitScene (the BVH build, on `threads` TBB threads);
// render_ms: the median of `runs` frames after one warm-up frame, the frame
// only (image allocation, ray generation, tracing, shading, the threads
// woken and waited for); rays: primary + shadow rays of one frame, which go
// to stderr too. firsthit_bench_scaling traces in double unless given
// --precision float; this traces in float, as Embree does.
//   firsthit_embree_reference [--threads N] [--runs K] [--max-level K] [--png OUT.png]
//                             [--bunny FILE.off] [--world] [--placements FILE.csv] [--scene FILE]
//                             [--width 4|8|16] [--verbose]
// --png writes the bunny's frame (the last icosphere's without the bunny);
// --bunny: default animations/meshes/bunny00.off of this source tree (bash
// scripts/fetch_meshes.sh fetches it); missing, the bunny row is left out.
// --world: the --bunny file is already in the world (as `firsthit export`
// writes a scene; scripts/bench_gltf.sh), not placed as the bunny is.
// --placements FILE.csv: instead, only the instancing benchmark's scene
// (scripts/bunny_grid.sh): the bunny placed by each row, as Embree
// instances (RTC_GEOMETRY_TYPE_INSTANCE) over one mesh scene.
// --scene FILE: instead, only that firsthit scene's (YAML or glTF) mesh
// instances, each distinct mesh an Embree scene (scripts/bench_gltf.sh).
#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/icosphere.h"
#include "meshes/mesh_loader.h"
#include "images/png_writer.h"
#include "render/image.h"
#include "scene/node.h"
#include "yaml/placements.h"
#include "yaml/scene_loader.h"

#ifndef FIRSTHIT_SOURCE_DIR
#define FIRSTHIT_SOURCE_DIR "."
#endif

namespace {

using fh::dvec3;
using Clock = std::chrono::steady_clock;

constexpr int kWidth = 800, kHeight = 800;
constexpr int kTile = 16;
constexpr float kInf = std::numeric_limits<float>::infinity();

struct V3 {
    float x, y, z;
};
V3 to_v3(const dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }

// A material's colour terms with the scene's lights, as firsthit's
// FlatScene computes them (in double, then rounded to float): ambient =
// intensity * ambient * light colour * material colour; diffuse, per unit n.l,
// = intensity * diffuse * light colour * material colour.
struct Shade {
    V3 ambient, diffuse;
};
constexpr double kAmbientLight = 0.006, kSun = 0.004, kLight = 255;
Shade shade_of(const dvec3& color, double ambient, double diffuse) {
    return {to_v3(kAmbientLight * ambient * kLight * color), to_v3(kSun * diffuse * kLight * color)};
}

struct SceneSpec {
    std::string name;
    std::vector<float> vertices;  // x y z per vertex
    std::vector<std::uint32_t> indices;  // 3 per triangle
    size_t triangles = 0;
    float floor_z = -3;  // the plane n.x = d with n = (0, 0, 1), d = floor_z
    Shade mesh, floor;
    // Empty: the mesh is the scene, in world space. Else the mesh is placed
    // once per matrix (object -> world) as Embree instances, and a hit's
    // object-space normal turned by its instance's normal matrix (the
    // inverse transpose), one matrix a lane.
    std::vector<glm::dmat4> instances;
    std::vector<std::array<V3, 3>> normal_matrices;  // rows
    // With instances of several meshes (--scene): each mesh, and the one
    // each instance places; empty: every instance places the mesh above.
    struct Part {
        std::vector<float> vertices;
        std::vector<std::uint32_t> indices;
    };
    std::vector<Part> parts;
    std::vector<int> instance_part;
};

const Shade kGrey = shade_of(dvec3(200), 0.1, 0.9);

// bench_scaling.cpp's scene: the icosphere (a triangle soup), grey, on a grey floor z = -3.
SceneSpec icosphere_scene(int level) {
    SceneSpec s;
    s.name = "icosphere" + std::to_string(level);
    const std::vector<fh::Triangle<double>> tris = fh::icosphere(level, 3.0, 0);
    s.vertices.reserve(tris.size() * 9);
    s.indices.reserve(tris.size() * 3);
    for (const auto& t : tris) {
        if (t.degenerate()) continue;  // firsthit leaves them out too (none here)
        for (const dvec3& p : {t.v0, t.v1, t.v2}) {
            s.indices.push_back(std::uint32_t(s.vertices.size() / 3));
            s.vertices.insert(s.vertices.end(), {float(p.x), float(p.y), float(p.z)});
        }
    }
    s.triangles = s.indices.size() / 3;
    s.floor_z = -3;
    s.mesh = s.floor = kGrey;
    return s;
}

// animations/bunny.yaml: the mesh scaled by 4.4743 and turned 90 degrees
// about x (composed as scene_loader.cpp's read_transform does: translate *
// rotate * scale), grey, on the floor z = -2.2078 of colour (140, 170, 200).
// Triangles the transform leaves without area are dropped, as firsthit does.
SceneSpec bunny_scene(const std::string& path, bool world) {
    const fh::MeshData mesh = fh::load_mesh(path);
    glm::dmat4 t(1.0);
    if (!world) {  // as animations/bunny.yaml places the bunny
        t = glm::rotate(t, glm::radians(90.0), glm::normalize(dvec3(1, 0, 0)));
        t = glm::scale(t, dvec3(4.4743));
    }
    std::vector<dvec3> p(mesh.positions.size());
    for (size_t i = 0; i < p.size(); ++i) p[i] = dvec3(t * glm::dvec4(mesh.positions[i], 1.0));
    SceneSpec s;
    s.name = world ? std::filesystem::path(path).stem().string() : "bunny";
    for (const dvec3& q : p) s.vertices.insert(s.vertices.end(), {float(q.x), float(q.y), float(q.z)});
    for (const auto& tri : mesh.triangles) {
        if (fh::Triangle<double>::make(p[tri[0]], p[tri[1]], p[tri[2]], 0).degenerate()) continue;
        s.indices.insert(s.indices.end(), {tri[0], tri[1], tri[2]});
    }
    s.triangles = s.indices.size() / 3;
    s.floor_z = -2.2078f;
    s.mesh = kGrey;
    s.floor = shade_of(dvec3(140, 170, 200), 0.1, 0.9);
    return s;
}

// bench/bunny_grid.sh's scene: the bunny in its own space, placed by each
// row of the placements CSV (read by firsthit's own reader, so both
// renderers get the same matrices), on the floor z = -3 of colour
// (140, 170, 200).
SceneSpec instanced_scene(const std::string& mesh_path, const std::string& placements) {
    const fh::MeshData mesh = fh::load_mesh(mesh_path);
    SceneSpec s;
    for (const dvec3& q : mesh.positions) s.vertices.insert(s.vertices.end(), {float(q.x), float(q.y), float(q.z)});
    for (const auto& tri : mesh.triangles) {
        if (fh::Triangle<double>::make(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]], 0)
                .degenerate())
            continue;
        s.indices.insert(s.indices.end(), {tri[0], tri[1], tri[2]});
    }
    for (const fh::Transform& t : fh::load_placements(placements).rows) {
        s.instances.push_back(t.matrix());
        const glm::dmat3 n = glm::inverseTranspose(glm::dmat3(s.instances.back()));
        s.normal_matrices.push_back({to_v3(glm::row(n, 0)), to_v3(glm::row(n, 1)), to_v3(glm::row(n, 2))});
    }
    s.name = "instances" + std::to_string(s.instances.size());
    s.triangles = s.indices.size() / 3 * s.instances.size();
    s.floor_z = -3;
    s.mesh = kGrey;
    s.floor = shade_of(dvec3(140, 170, 200), 0.1, 0.9);
    return s;
}

// A firsthit scene file's mesh instances (--scene: a YAML scene or a glTF
// model, read by firsthit's own loaders, its nodes placed): each distinct
// mesh one Embree scene, each instance an Embree instance of it with the
// same matrix -- the two levels firsthit traces, on Embree. The floor is the
// scene's first plane (normal (0, 0, 1)); camera, lights and colours are the
// benchmark's, as for the bunny.
SceneSpec scene_instances(const std::string& path) {
    fh::SceneFile file = fh::load_scene(path);
    fh::Scene& scene = file.scene;
    fh::place_nodes(scene);
    SceneSpec s;
    s.name = std::filesystem::path(path).stem().string() + "_instances";
    for (const fh::SceneMesh& m : scene.meshes) {
        SceneSpec::Part part;
        const std::vector<dvec3>& p = m.mesh->positions;
        for (const dvec3& q : p) part.vertices.insert(part.vertices.end(), {float(q.x), float(q.y), float(q.z)});
        for (const auto& tri : m.mesh->triangles) {
            if (fh::Triangle<double>::make(p[tri[0]], p[tri[1]], p[tri[2]], 0).degenerate()) continue;
            part.indices.insert(part.indices.end(), {tri[0], tri[1], tri[2]});
        }
        s.parts.push_back(std::move(part));
    }
    for (const fh::Instance& i : scene.instances) {
        s.instances.push_back(i.to_world);
        s.instance_part.push_back(i.mesh);
        s.triangles += s.parts[size_t(i.mesh)].indices.size() / 3;
        const glm::dmat3 n = glm::inverseTranspose(glm::dmat3(i.to_world));
        s.normal_matrices.push_back({to_v3(glm::row(n, 0)), to_v3(glm::row(n, 1)), to_v3(glm::row(n, 2))});
    }
    if (s.instances.empty()) throw std::runtime_error(path + ": no mesh instances");
    s.floor_z = scene.planes.empty() ? -3.0f : float(scene.planes.front().distance);
    s.mesh = kGrey;
    s.floor = shade_of(dvec3(140, 170, 200), 0.1, 0.9);
    return s;
}

// firsthit's CameraRays<float> (src/scene/camera.h, camera.cpp): the basis in
// double, w = normalize(-look_at), u = normalize(up x w), v = w x u, then in
// float: direction = normalize(-d w + (x0 + dx px) u + (y0 - dy py) v) with the
// image plane 10 units tall.
struct CameraRays {
    V3 eye, u, v, forward;
    float x0, y0, dx, dy;

    CameraRays() {
        const dvec3 view_point(0, -12, 6), look_at(0, 12, -6), up(0, 0, 1);
        const double projection_distance = 10;
        const dvec3 w = glm::normalize(-look_at);
        const dvec3 uu = glm::normalize(glm::cross(up, w));
        const dvec3 vv = glm::cross(w, uu);
        eye = to_v3(view_point);
        u = to_v3(uu);
        v = to_v3(vv);
        forward = to_v3(-w * projection_distance);
        const double half_height = 10.0, half_width = 10.0 * kWidth / kHeight;
        x0 = float(-half_width);
        y0 = float(half_height);
        dx = float(2 * half_width / kWidth);
        dy = float(2 * half_height / kHeight);
    }

    V3 direction(float px, float py) const {
        const float a = x0 + dx * px, b = y0 - dy * py;
        const V3 d{forward.x + (a * u.x + b * v.x), forward.y + (a * u.y + b * v.y),
                   forward.z + (a * u.z + b * v.z)};
        const float inv = 1.0f / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        return {d.x * inv, d.y * inv, d.z * inv};
    }
};

// The light the shading sees: towards the sun, unit.
const V3 kToLight = to_v3(-glm::normalize(dvec3(-1, 1, -2)));

struct Counts {
    std::uint64_t primary = 0, shadow = 0;
};

// A packet's rays, by width: Embree's ray structures and calls for packets
// of 4, 8 and 16, the pixel block a packet covers (4 x 4, 4 x 2, 2 x 2), and
// W lanes as one value (GCC's vector extensions: one register of the
// packet's width) for the code around the Embree calls. The frame uses the
// widest packets this CPU's Embree traces natively (16 with AVX-512, 8 with
// AVX2), as firsthit's packets follow the CPU's vector width: Embree
// emulates a wider packet ray by ray.
template <typename RayHitT, typename RayT, typename VFT, typename VIT, int BlockX,
          void (*Intersect)(const int*, RTCScene, RTCIntersectContext*, RayHitT*),
          void (*Occluded)(const int*, RTCScene, RTCIntersectContext*, RayT*)>
struct PacketOf {
    using RayHit = RayHitT;
    using Ray = RayT;
    using VF = VFT;
    using VI = VIT;
    static constexpr int kBlockX = BlockX;
    static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) { Intersect(v, s, c, r); }
    static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, Ray* r) { Occluded(v, s, c, r); }
};
// (Vector types spelled out per width: GCC drops a vector_size that depends
// on a template parameter.)
typedef float VF16 __attribute__((vector_size(64)));
typedef std::int32_t VI16 __attribute__((vector_size(64)));
typedef float VF8 __attribute__((vector_size(32)));
typedef std::int32_t VI8 __attribute__((vector_size(32)));
typedef float VF4 __attribute__((vector_size(16)));
typedef std::int32_t VI4 __attribute__((vector_size(16)));
template <int W>
struct Packet;
template <>
struct Packet<16> : PacketOf<RTCRayHit16, RTCRay16, VF16, VI16, 4, rtcIntersect16, rtcOccluded16> {};
template <>
struct Packet<8> : PacketOf<RTCRayHit8, RTCRay8, VF8, VI8, 4, rtcIntersect8, rtcOccluded8> {};
template <>
struct Packet<4> : PacketOf<RTCRayHit4, RTCRay4, VF4, VI4, 2, rtcIntersect4, rtcOccluded4> {};

template <typename V>
inline V load(const void* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store(void* p, const auto& v) { std::memcpy(p, &v, sizeof v); }
template <typename VF>
inline VF splat(float x) {
    return VF{} + x;
}
template <typename VF>
inline VF vabs(VF v) {
    using VI = decltype(v < v);
    return VF(VI(v) & 0x7fffffff);
}
template <typename VF>
inline VF vmax(VF a, VF b) {
    return a > b ? a : b;
}
template <typename VF>
inline VF vmin(VF a, VF b) {
    return a < b ? a : b;
}
template <typename VF>
inline VF rsqrt(VF v) {  // 1 / sqrt, lane by lane: one vsqrtps and one vdivps
    VF r;
    for (int i = 0; i < int(sizeof v / sizeof(float)); ++i) r[i] = std::sqrt(v[i]);
    return 1.0f / r;
}
template <typename VI>
inline int count(VI m) {
    int n = 0;
    for (int i = 0; i < int(sizeof m / sizeof(std::int32_t)); ++i) n += m[i] != 0;
    return n;
}

// One block of W pixels (Packet<W>::kBlockX wide), its top-left corner
// (bx, by): a packet of W camera rays, then a packet of shadow rays for the
// lanes lit by the sun. The steps around the two Embree calls work on all
// lanes at once (what Embree's own tutorials get from ISPC), so that the
// frame time is Embree's, not that of scalar code around it.
template <int W>
void trace_block(RTCScene scene, const SceneSpec& spec, const CameraRays& cam, int bx, int by,
                 fh::Image& image, Counts& counts) {
    using P = Packet<W>;
    using VF = typename P::VF;
    using VI = typename P::VI;
    VI lane;
    for (int i = 0; i < W; ++i) lane[i] = i;
    const VI xi = bx + lane % P::kBlockX, yi = by + lane / P::kBlockX;
    const VI valid = (xi < kWidth) & (yi < kHeight);
    // Lanes past the image's edge repeat its last pixel, inactive.
    const VF px = __builtin_convertvector(xi < kWidth ? xi : kWidth - 1, VF) + 0.5f;
    const VF py = __builtin_convertvector(yi < kHeight ? yi : kHeight - 1, VF) + 0.5f;
    const VF a = cam.x0 + cam.dx * px, b = cam.y0 - cam.dy * py;
    VF dx = cam.forward.x + (a * cam.u.x + b * cam.v.x);
    VF dy = cam.forward.y + (a * cam.u.y + b * cam.v.y);
    VF dz = cam.forward.z + (a * cam.u.z + b * cam.v.z);
    const VF inv_len = rsqrt(dx * dx + dy * dy + dz * dz);
    dx *= inv_len, dy *= inv_len, dz *= inv_len;

    alignas(64) typename P::RayHit rh;
    const VF zero = splat<VF>(0), inf = splat<VF>(kInf);
    const VI none = VI{} + int(RTC_INVALID_GEOMETRY_ID), all_bits = VI{} - 1;
    store(rh.ray.org_x, splat<VF>(cam.eye.x));
    store(rh.ray.org_y, splat<VF>(cam.eye.y));
    store(rh.ray.org_z, splat<VF>(cam.eye.z));
    store(rh.ray.dir_x, dx);
    store(rh.ray.dir_y, dy);
    store(rh.ray.dir_z, dz);
    store(rh.ray.tnear, zero);
    store(rh.ray.tfar, inf);
    store(rh.ray.time, zero);
    store(rh.ray.mask, all_bits);
    store(rh.ray.id, lane);
    store(rh.ray.flags, VI{});
    store(rh.hit.Ng_x, zero);
    store(rh.hit.Ng_y, zero);
    store(rh.hit.Ng_z, zero);
    store(rh.hit.geomID, none);
    store(rh.hit.instID[0], none);
    alignas(64) std::int32_t valid_mask[W];
    store(valid_mask, valid);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    P::intersect(valid_mask, scene, &context, &rh);

    // The nearest hit of each lane, the floor included: t = (d - n.o) /
    // (n.dir), n = (0, 0, 1); a (nearly) parallel ray misses it, as in
    // firsthit's Plane. The unit normal, facing the ray.
    const VF ox = splat<VF>(cam.eye.x), oy = splat<VF>(cam.eye.y), oz = splat<VF>(cam.eye.z);
    const VI mesh_hit = valid & (load<VI>(rh.hit.geomID) != none);
    const VF t_mesh = mesh_hit ? load<VF>(rh.ray.tfar) : inf;
    const VF t_floor = (spec.floor_z - oz) / dz;
    const VI on_floor = valid & (vabs(dz) >= 1e-6f) & (t_floor > 0) & (t_floor < t_mesh);
    const VI on_mesh = mesh_hit & ~on_floor;
    const VI hit = on_mesh | on_floor;
    const VF t = on_floor ? t_floor : t_mesh;
    VF nx = load<VF>(rh.hit.Ng_x), ny = load<VF>(rh.hit.Ng_y), nz = load<VF>(rh.hit.Ng_z);
    if (!spec.instances.empty()) {  // object-space normals: each turned by its instance's matrix
        const VI inst = load<VI>(rh.hit.instID[0]);
        for (int i = 0; i < W; ++i) {
            if (!on_mesh[i]) continue;
            const auto& m = spec.normal_matrices[size_t(inst[i])];
            const float x = nx[i], y = ny[i], z = nz[i];
            nx[i] = m[0].x * x + m[0].y * y + m[0].z * z;
            ny[i] = m[1].x * x + m[1].y * y + m[1].z * z;
            nz[i] = m[2].x * x + m[2].y * y + m[2].z * z;
        }
    }
    const VF g2 = nx * nx + ny * ny + nz * nz;
    const VF inv_g = rsqrt(g2 > 0 ? g2 : splat<VF>(1));
    nx = on_floor ? zero : nx * inv_g;
    ny = on_floor ? zero : ny * inv_g;
    nz = on_floor ? splat<VF>(1) : nz * inv_g;
    const VF facing = nx * dx + ny * dy + nz * dz > 0 ? splat<VF>(-1) : splat<VF>(1);
    nx *= facing, ny *= facing, nz *= facing;
    const VF n_dot_l = nx * kToLight.x + ny * kToLight.y + nz * kToLight.z;
    VI lit = hit & (n_dot_l > 0);

    // Shadow rays from the lit lanes, pushed off the surface along the
    // normal by firsthit's float margin (src/core/offset.h):
    // 1e-7 + 1e-5 * max |coordinate|.
    const int lit_count = count(lit);
    counts.primary += unsigned(count(valid));
    counts.shadow += unsigned(lit_count);
    if (lit_count > 0) {
        const VF hx = ox + t * dx, hy = oy + t * dy, hz = oz + t * dz;
        const VF eps = 1e-7f + 1e-5f * vmax(vabs(hx), vmax(vabs(hy), vabs(hz)));
        const VF sz = lit ? hz + eps * nz : zero;
        alignas(64) typename P::Ray shadow;
        store(shadow.org_x, lit ? hx + eps * nx : zero);
        store(shadow.org_y, lit ? hy + eps * ny : zero);
        store(shadow.org_z, sz);
        store(shadow.dir_x, splat<VF>(kToLight.x));
        store(shadow.dir_y, splat<VF>(kToLight.y));
        store(shadow.dir_z, splat<VF>(kToLight.z));
        store(shadow.tnear, zero);
        store(shadow.tfar, inf);
        store(shadow.time, zero);
        store(shadow.mask, all_bits);
        store(shadow.id, lane);
        store(shadow.flags, VI{});
        alignas(64) std::int32_t lit_mask[W];
        store(lit_mask, lit);
        RTCIntersectContext shadow_context;
        rtcInitIntersectContext(&shadow_context);
        // Debian's Embree 3.13.5 never returns from a coherent rtcOccluded16
        // into instances on AVX-512 (seen here, both threads spinning in it
        // for 15 minutes); incoherent, it does -- and measured faster
        // (1 bunny instance: 10.0 ms against 15.6 ms with 8-wide packets).
        shadow_context.flags = spec.instances.empty() ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                      : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
        P::occluded(lit_mask, scene, &shadow_context, &shadow);
        // Blocked by the mesh (Embree sets tfar = -inf), or by the floor,
        // analytically (never here: the light is above it).
        lit &= load<VF>(shadow.tfar) >= 0;
        if (std::abs(kToLight.z) >= 1e-6f) lit &= ~((spec.floor_z - sz) / kToLight.z > 0);
    }

    // Colours: ambient + n.l diffuse where lit; the sky is firsthit's
    // (src/render/background.h): (255, 255 s, 0), s = clamp((dir.z + 1) / 2,
    // 0, 1). Clamped to [0, 255] and rounded as firsthit's pixels are.
    const Shade& m = spec.mesh;
    const Shade& f = spec.floor;
    const VF d = lit ? n_dot_l : zero;
    const VF s = vmin(vmax((dz + 1.0f) / 2.0f, zero), splat<VF>(1));
    const VF r = on_mesh ? m.ambient.x + d * m.diffuse.x
                         : on_floor ? f.ambient.x + d * f.diffuse.x : splat<VF>(255);
    const VF g = on_mesh ? m.ambient.y + d * m.diffuse.y : on_floor ? f.ambient.y + d * f.diffuse.y : 255.0f * s;
    const VF bl = on_mesh ? m.ambient.z + d * m.diffuse.z : on_floor ? f.ambient.z + d * f.diffuse.z : zero;
    auto to_byte = [&](VF v) { return __builtin_convertvector(vmin(vmax(v, zero), splat<VF>(255)) + 0.5f, VI); };
    const VI r8 = to_byte(r), g8 = to_byte(g), b8 = to_byte(bl);
    for (int i = 0; i < W; ++i) {
        if (!valid[i]) continue;
        std::uint8_t* p = image.pixel(xi[i], yi[i]);
        p[0] = std::uint8_t(r8[i]), p[1] = std::uint8_t(g8[i]), p[2] = std::uint8_t(b8[i]);
    }
}

struct Frame {
    fh::Image image;
    Counts counts;
    double ms = 0;
};

// The frames' threads: started once and woken for each frame (as firsthit's
// ThreadPool), not started per frame -- a thread started for a frame may run
// on its parent's core for the first milliseconds, and frames then took up
// to 1.8 times as long here. run(fn) calls fn(worker) on every thread, the
// caller's as worker 0, and returns when all are done.
class Workers {
public:
    explicit Workers(int threads) {
        for (int w = 1; w < threads; ++w) threads_.emplace_back([this, w] { loop(w); });
    }
    ~Workers() {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (auto& t : threads_) t.join();
    }
    int size() const { return int(threads_.size()) + 1; }
    void run(const std::function<void(int)>& fn) {
        {
            std::lock_guard lock(mutex_);
            job_ = &fn;
            busy_ = int(threads_.size());
            ++generation_;
        }
        wake_.notify_all();
        fn(0);
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return busy_ == 0; });
        job_ = nullptr;
    }

private:
    void loop(int worker) {
        // Embree's advice for every thread that traces.
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        unsigned seen = 0;
        for (;;) {
            const std::function<void(int)>* job;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
                if (stopping_) return;
                seen = generation_;
                job = job_;
            }
            (*job)(worker);
            std::lock_guard lock(mutex_);
            if (--busy_ == 0) done_.notify_all();
        }
    }

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(int)>* job_ = nullptr;
    int busy_ = 0;
    unsigned generation_ = 0;
    bool stopping_ = false;
};

// How a frame traces its blocks: the packet width W and trace_block<W>.
struct Blocks {
    int width;  // W
    int block_x, block_y;
    void (*trace)(RTCScene, const SceneSpec&, const CameraRays&, int, int, fh::Image&, Counts&);
};
template <int W>
Blocks blocks_of() {
    return {W, Packet<W>::kBlockX, W / Packet<W>::kBlockX, trace_block<W>};
}
// width: 4, 8 or 16.
Blocks blocks_of(int width) { return width == 16 ? blocks_of<16>() : width == 8 ? blocks_of<8>() : blocks_of<4>(); }

// The widest packets Embree traces natively on this CPU (16, 8 or 4).
int native_width(RTCDevice device) {
    if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
    return rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) ? 8 : 4;
}

// One frame: 16 x 16 tiles handed out by an atomic counter to the threads.
Frame render(RTCScene scene, const SceneSpec& spec, const CameraRays& cam, const Blocks& blocks,
             Workers& workers) {
    const auto start = Clock::now();
    Frame f;
    f.image = fh::Image(kWidth, kHeight);
    const int tiles_x = (kWidth + kTile - 1) / kTile, tiles = tiles_x * ((kHeight + kTile - 1) / kTile);
    std::atomic<int> next{0};
    struct alignas(64) PaddedCounts {
        Counts c;
    };
    std::vector<PaddedCounts> counts(static_cast<size_t>(workers.size()));
    workers.run([&](int worker) {
        Counts& c = counts[size_t(worker)].c;
        for (int t; (t = next.fetch_add(1, std::memory_order_relaxed)) < tiles;) {
            const int x0 = (t % tiles_x) * kTile, y0 = (t / tiles_x) * kTile;
            for (int y = y0; y < std::min(y0 + kTile, kHeight); y += blocks.block_y)
                for (int x = x0; x < std::min(x0 + kTile, kWidth); x += blocks.block_x)
                    blocks.trace(scene, spec, cam, x, y, f.image, c);
        }
    });
    for (const auto& c : counts) f.counts.primary += c.c.primary, f.counts.shadow += c.c.shadow;
    f.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return f;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

void on_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "embree_reference: Embree error %d: %s\n", int(code), message ? message : "");
    std::exit(1);
}

// The scene's mesh as one Embree triangle geometry, in a scene not yet
// committed; or, with instances, that mesh in a scene of its own (built
// here) placed by one instance geometry per matrix in the scene returned.
RTCScene new_scene(RTCDevice device, const SceneSpec& spec) {
    if (!spec.instances.empty()) {
        // Each mesh in a scene of its own (parts, or the one mesh).
        std::vector<RTCScene> meshes;
        for (size_t k = 0; k < std::max<size_t>(spec.parts.size(), 1); ++k) {
            SceneSpec object;
            object.vertices = spec.parts.empty() ? spec.vertices : spec.parts[k].vertices;
            object.indices = spec.parts.empty() ? spec.indices : spec.parts[k].indices;
            object.triangles = object.indices.size() / 3;  // spec counts them once per instance
            meshes.push_back(new_scene(device, object));
            rtcCommitScene(meshes.back());
        }
        RTCScene top = rtcNewScene(device);
        rtcSetSceneFlags(top, RTC_SCENE_FLAG_NONE);
        rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_MEDIUM);
        for (size_t k = 0; k < spec.instances.size(); ++k) {
            const glm::dmat4& m = spec.instances[k];
            RTCGeometry inst = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(inst, meshes[spec.parts.empty() ? 0 : size_t(spec.instance_part[k])]);
            float xfm[12];  // 3 x 4, column major
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 3; ++r) xfm[3 * c + r] = float(m[c][r]);
            rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
            rtcCommitGeometry(inst);
            rtcAttachGeometry(top, inst);
            rtcReleaseGeometry(inst);
        }
        for (RTCScene mesh : meshes) rtcReleaseScene(mesh);  // the instances hold them
        return top;
    }
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_NONE);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    void* v = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                      spec.vertices.size() / 3);
    std::memcpy(v, spec.vertices.data(), spec.vertices.size() * sizeof(float));
    void* idx = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                        spec.triangles);
    std::memcpy(idx, spec.indices.data(), spec.indices.size() * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    return scene;
}

// Builds the scene (build_ms: rtcCommitScene only), renders a warm-up frame
// and `runs` timed ones, prints the CSV row; returns the last frame.
Frame run(RTCDevice device, const SceneSpec& spec, const Blocks& blocks, Workers& workers, int runs) {
    RTCScene scene = new_scene(device, spec);
    const auto start = Clock::now();
    rtcCommitScene(scene);
    const double build_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();

    const CameraRays cam;
    Frame f = render(scene, spec, cam, blocks, workers);  // warm-up
    std::vector<double> ms;
    for (int k = 0; k < runs; ++k) {
        f = render(scene, spec, cam, blocks, workers);
        ms.push_back(f.ms);
    }
    rtcReleaseScene(scene);
    const double m = median(ms);
    const std::uint64_t rays = f.counts.primary + f.counts.shadow;
    std::printf("%s,%zu,%.3f,%.3f,%.4g\n", spec.name.c_str(), spec.triangles, build_ms, m,
                double(rays) / (m / 1000));
    std::fflush(stdout);
    std::fprintf(stderr, "# %s: %llu primary + %llu shadow = %llu rays per frame\n", spec.name.c_str(),
                 (unsigned long long)f.counts.primary, (unsigned long long)f.counts.shadow,
                 (unsigned long long)rays);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 2, runs = 9, max_level = 8, width = 0;
    bool verbose = false, unknown = false, world = false;
    std::string png, placements, scene_file;
    std::string bunny = std::string(FIRSTHIT_SOURCE_DIR) + "/animations/meshes/bunny00.off";
    for (int i = 1; i < argc; ++i) {
        const bool has_value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--threads") && has_value) threads = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--runs") && has_value) runs = std::max(1, std::atoi(argv[++i]));
        else if (!std::strcmp(argv[i], "--max-level") && has_value) max_level = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--png") && has_value) png = argv[++i];
        else if (!std::strcmp(argv[i], "--width") && has_value) width = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--bunny") && has_value) bunny = argv[++i];
        else if (!std::strcmp(argv[i], "--placements") && has_value) placements = argv[++i];
        else if (!std::strcmp(argv[i], "--scene") && has_value) scene_file = argv[++i];
        else if (!std::strcmp(argv[i], "--verbose")) verbose = true;
        else if (!std::strcmp(argv[i], "--world")) world = true;
        else unknown = true;
        if (unknown || (width != 0 && width != 4 && width != 8 && width != 16)) {
            std::fprintf(stderr,
                         "usage: firsthit_embree_reference [--threads N] [--runs K] [--max-level K] "
                         "[--png OUT.png] [--bunny FILE.off] [--world] [--placements FILE.csv] [--scene FILE] "
                         "[--width 4|8|16] [--verbose]\n");
            return 2;
        }
    }
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    // threads: the BVH builder's TBB threads; the frames use their own threads.
    const std::string config = "threads=" + std::to_string(threads) + (verbose ? ",verbose=1" : "");
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) {
        std::fprintf(stderr, "embree_reference: rtcNewDevice failed (error %d)\n",
                     int(rtcGetDeviceError(nullptr)));
        return 1;
    }
    rtcSetDeviceErrorFunction(device, on_error, nullptr);
    const long version = long(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));
    const int native = native_width(device);
    const Blocks blocks = blocks_of(width ? width : native);
    std::fprintf(stderr, "# Embree %ld.%ld.%ld, %d-wide packets (%s; native: %d), tasking: %s, threads: %d\n",
                 version / 10000, version / 100 % 100, version % 100, blocks.width,
                 blocks.width > native ? "emulated" : "native", native,
                 rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_TASKING_SYSTEM) == 1 ? "TBB" : "internal/other",
                 threads);

    // Warm the device up (its build threads start on the first commit).
    RTCScene warm = new_scene(device, icosphere_scene(1));
    rtcCommitScene(warm);
    rtcReleaseScene(warm);

    std::printf("scene,triangles,build_ms,render_ms,rays_per_second\n");
    std::fflush(stdout);
    Workers workers(threads);
    Frame last;
    if (!placements.empty() || !scene_file.empty()) {  // the instancing benchmark's scene, or a scene's, alone
        try {
            last = run(device, scene_file.empty() ? instanced_scene(bunny, placements) : scene_instances(scene_file),
                       blocks, workers, runs);
            if (!png.empty()) fh::write_png(png, last.image);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "embree_reference: %s\n", e.what());
            return 1;
        }
        rtcReleaseDevice(device);
        return 0;
    }
    for (int level = 1; level <= max_level; ++level) last = run(device, icosphere_scene(level), blocks, workers, runs);

    bool have_bunny = false;
    if (!std::filesystem::exists(bunny)) {
        std::fprintf(stderr, "embree_reference: %s is missing, no bunny row (bash scripts/fetch_meshes.sh)\n",
                     bunny.c_str());
    } else {
        try {
            last = run(device, bunny_scene(bunny, world), blocks, workers, runs);
            have_bunny = true;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "embree_reference: %s\n", e.what());
            return 1;
        }
    }
    rtcReleaseDevice(device);
    if (!png.empty()) {
        if (last.image.width == 0) {
            std::fprintf(stderr, "embree_reference: no frame rendered, %s not written\n", png.c_str());
            return 1;
        }
        if (!have_bunny) std::fprintf(stderr, "embree_reference: no bunny; %s is the last icosphere\n", png.c_str());
        try {
            fh::write_png(png, last.image);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "embree_reference: %s\n", e.what());
            return 1;
        }
    }
    return 0;
}
