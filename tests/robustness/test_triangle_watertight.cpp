// The closed tetrahedron of the report (docs/model.md section 2)
// is watertight -- rays aimed from outside exactly at its edges and vertices
// all enter it through a face that faces them -- and degenerate triangles
// (no area, collinear, a repeated vertex) never hit and never give NaN.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "geometry/triangle.h"
#include "robust_util.h"

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class TriangleRobust : public ::testing::Test {};
TYPED_TEST_SUITE(TriangleRobust, Scalars);

// Report Table 4.
const std::array<dvec3, 4> kVertex = {dvec3(-5, 5, 0), dvec3(-7, 5, 0), dvec3(-6, 7, 0), dvec3(-6, 6, 5)};
const std::array<std::array<int, 3>, 4> kFace = {{{0, 1, 2}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}}};
const std::array<std::array<int, 2>, 6> kEdge = {{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

dvec3 centroid() { return (kVertex[0] + kVertex[1] + kVertex[2] + kVertex[3]) / 4.0; }

// Outward unit normal of face f.
dvec3 outward(int f) {
    const auto& v = kFace[size_t(f)];
    dvec3 n = glm::normalize(glm::cross(kVertex[size_t(v[1])] - kVertex[size_t(v[0])],
                                        kVertex[size_t(v[2])] - kVertex[size_t(v[0])]));
    if (glm::dot(n, kVertex[size_t(v[0])] - centroid()) < 0) n = -n;
    return n;
}

bool face_has(int f, int vertex) {
    for (int v : kFace[size_t(f)])
        if (v == vertex) return true;
    return false;
}

// A random point strictly inside the tetrahedron.
dvec3 interior_point(std::mt19937_64& rng) {
    std::gamma_distribution<double> g(1, 1);
    double w[4], sum = 0;
    for (double& x : w) sum += (x = g(rng) + 1e-3);
    dvec3 p(0);
    for (int i = 0; i < 4; ++i) p += (w[i] / sum) * kVertex[size_t(i)];
    return p;
}

// Item 4: >= 1e6 rays (a quarter of that under the sanitizers), aimed from
// outside at points of the six edges and at the four vertices, each from a
// direction in which it enters the solid there (every face at that edge or
// vertex faces the ray, n.d <= -0.02). Each must hit, and its nearest hit must
// be one of those front faces at about the aimed distance: a ray that slipped
// between two triangles would find the back of the solid, or nothing.
TYPED_TEST(TriangleRobust, TetrahedronIsWatertightAtEdgesAndVertices) {
    using T = TypeParam;
    std::array<Triangle<T>, 4> tri;
    std::array<dvec3, 4> out;
    for (int f = 0; f < 4; ++f) {
        const auto& v = kFace[size_t(f)];
        tri[size_t(f)] = Triangle<T>::make(Vec3<T>(kVertex[size_t(v[0])]), Vec3<T>(kVertex[size_t(v[1])]),
                                           Vec3<T>(kVertex[size_t(v[2])]), f);
        out[size_t(f)] = outward(f);
    }
    const int rays = kSanitized ? 250000 : 1000000;
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> u01(0, 1);
    int misses = 0, through_back = 0, wrong_distance = 0, nan = 0, aimed_at_vertex = 0;
    for (int i = 0; i < rays; ++i) {
        // One ray in five at a vertex, the others along an edge: at dyadic
        // fractions (exact in T) every other time, at random ones otherwise.
        dvec3 target;
        std::array<bool, 4> incident{};
        if (i % 5 == 0) {
            const int v = int(u01(rng) * 4) & 3;
            target = kVertex[size_t(v)];
            for (int f = 0; f < 4; ++f) incident[size_t(f)] = face_has(f, v);
            ++aimed_at_vertex;
        } else {
            const auto& e = kEdge[size_t(int(u01(rng) * 6) % 6)];
            const double s = (i % 2) ? std::ldexp(double(1 + int(u01(rng) * 255)), -8)  // k/256
                                     : 0.001 + 0.998 * u01(rng);
            target = kVertex[size_t(e[0])] + s * (kVertex[size_t(e[1])] - kVertex[size_t(e[0])]);
            for (int f = 0; f < 4; ++f) incident[size_t(f)] = face_has(f, e[0]) && face_has(f, e[1]);
        }
        // A direction into the solid at the target, with every incident face
        // facing it by a margin.
        dvec3 d;
        for (;;) {
            d = glm::normalize(interior_point(rng) - target);
            bool ok = true;
            for (int f = 0; f < 4; ++f)
                if (incident[size_t(f)] && glm::dot(out[size_t(f)], d) > -0.02) ok = false;
            if (ok) break;
        }
        const double distance = std::pow(10.0, -1 + 4 * u01(rng));  // 0.1 .. 1000
        const Vec3<T> o(target - distance * d);
        const Vec3<T> dir(glm::normalize(target - dvec3(o)));
        const Ray<T> ray{o, dir};
        // The nearest hit, as closest_hits keeps it: the first of equal ones.
        T best = kInfinity<T>;
        int face = -1;
        for (int f = 0; f < 4; ++f) {
            const T t = tri[size_t(f)].intersect(ray, T(0), best);
            if (std::isnan(t)) ++nan;
            if (t < best) {
                best = t;
                face = f;
            }
        }
        if (face < 0) {
            ++misses;
        } else if (!incident[size_t(face)] || glm::dot(out[size_t(face)], dvec3(dir)) >= 0) {
            ++through_back;
        } else {
            // The distance along the ray as traced -- its origin and direction
            // rounded to T -- to the plane of the face it hit, in double. (Not
            // `distance`: at n.d = 0.02, rounding the origin to float alone
            // moves the hit by ulp/0.02 ~ 1e-5 along the ray.)
            // The origin is read back through memory. Seen here with GCC 12
            // at -O2 and -O3: double(o.x) printed more bits than a float
            // holds -- the double o was rounded from -- and the difference
            // went away with -fno-tree-slp-vectorize.
            volatile T traced[3] = {o.x, o.y, o.z};
            const dvec3 origin(traced[0], traced[1], traced[2]);
            const dvec3 n = out[size_t(face)], on_face = kVertex[size_t(kFace[size_t(face)][0])];
            const double exact = glm::dot(n, on_face - origin) / glm::dot(n, dvec3(dir));
            if (std::abs(double(best) - exact) > 1e-5 * exact + 1e-5) ++wrong_distance;
        }
    }
    EXPECT_EQ(nan, 0);
    EXPECT_EQ(misses, 0) << "of " << rays << " rays aimed at edges and vertices";
    EXPECT_EQ(through_back, 0) << "rays that slipped between two front faces";
    EXPECT_EQ(wrong_distance, 0);
    EXPECT_GT(aimed_at_vertex, rays / 6);
}

// Also from far away (1e4 .. 1e6 in double, 1e3 .. 1e4 in float, where the
// rounded direction still passes within ~1e-3 of the aimed point): every ray
// at an edge's midpoint region hits a front face.
TYPED_TEST(TriangleRobust, WatertightFromFarAway) {
    using T = TypeParam;
    std::array<Triangle<T>, 4> tri;
    for (int f = 0; f < 4; ++f) {
        const auto& v = kFace[size_t(f)];
        tri[size_t(f)] = Triangle<T>::make(Vec3<T>(kVertex[size_t(v[0])]), Vec3<T>(kVertex[size_t(v[1])]),
                                           Vec3<T>(kVertex[size_t(v[2])]), f);
    }
    const double lo = std::is_same_v<T, float> ? 3 : 4, hi = std::is_same_v<T, float> ? 4 : 6;
    std::mt19937_64 rng(45);
    std::uniform_real_distribution<double> u01(0, 1);
    int misses = 0;
    for (int i = 0; i < 100000; ++i) {
        const auto& e = kEdge[size_t(i % 6)];
        const dvec3 target = kVertex[size_t(e[0])] + (0.1 + 0.8 * u01(rng)) * (kVertex[size_t(e[1])] - kVertex[size_t(e[0])]);
        dvec3 d;
        for (;;) {
            d = glm::normalize(interior_point(rng) - target);
            bool ok = true;
            for (int f = 0; f < 4; ++f)
                if (face_has(f, e[0]) && face_has(f, e[1]) && glm::dot(outward(f), d) > -0.05) ok = false;
            if (ok) break;
        }
        const Vec3<T> o(target - std::pow(10.0, lo + (hi - lo) * u01(rng)) * d);
        const Ray<T> ray{o, Vec3<T>(glm::normalize(target - dvec3(o)))};
        T best = kInfinity<T>;
        for (const auto& t : tri) best = std::min(best, t.intersect(ray, T(0), best));
        misses += best == kInfinity<T>;
    }
    EXPECT_EQ(misses, 0);
}

// Item 5: triangles without area.
template <typename T>
std::vector<std::array<dvec3, 3>> degenerate_triangles(std::mt19937_64& rng) {
    std::vector<std::array<dvec3, 3>> out;
    const dvec3 a(0.1, -2.3, 4.7), b(1.9, 0.6, -0.35);
    out.push_back({a, a, a});                                              // a point
    out.push_back({a, a, b});                                              // repeated vertex
    out.push_back({a, b, a});
    out.push_back({b, a, a});
    out.push_back({dvec3(0), dvec3(1, 1, 1), dvec3(2, 2, 2)});            // collinear, exact
    out.push_back({dvec3(2, 2, 2), dvec3(0), dvec3(1, 1, 1)});            // middle vertex last
    out.push_back({dvec3(-6, 6, 5), dvec3(-6, 6, 5), dvec3(-6, 7, 0)});  // a tetrahedron edge, twice
    for (int i = 0; i < 20; ++i) {                                         // collinear, inexact
        const dvec3 p = 5.0 * random_unit(rng), e = random_unit(rng);
        std::uniform_real_distribution<double> u(-3, 3);
        out.push_back({p, p + u(rng) * e, p + u(rng) * e});
    }
    return out;
}

TYPED_TEST(TriangleRobust, DegenerateTrianglesNeverHitNorNaN) {
    using T = TypeParam;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u01(0, 1);
    int hits = 0, nan = 0, nonzero_normal = 0;
    for (const auto& v : degenerate_triangles<T>(rng)) {
        const auto tri = Triangle<T>::make(Vec3<T>(v[0]), Vec3<T>(v[1]), Vec3<T>(v[2]), 0);
        if (tri.normal != Vec3<T>(0)) ++nonzero_normal;
        for (int i = 0; i < 20000; ++i) {
            // Aim at a point of the segment (or at the point), from any side,
            // along the segment's own line too.
            const int k = int(u01(rng) * 3) % 3;
            const double s = u01(rng);
            const dvec3 target = v[size_t(k)] + s * (v[size_t((k + 1) % 3)] - v[size_t(k)]);
            dvec3 d = random_unit(rng);
            if (i % 50 == 0 && v[1] != v[0]) d = glm::normalize(v[1] - v[0]);
            if (i % 50 == 1 && v[2] != v[0]) d = glm::normalize(v[0] - v[2]);
            const Vec3<T> o(target - (0.5 + 10 * u01(rng)) * d);
            const T t = tri.intersect({o, Vec3<T>(d)}, T(0), kInfinity<T>);
            nan += std::isnan(t);
            hits += t != kInfinity<T>;
        }
    }
    EXPECT_EQ(nonzero_normal, 0) << "degenerate triangles with a normal";
    EXPECT_EQ(hits, 0);
    EXPECT_EQ(nan, 0);
}

// Item 5 and 11 in a render: degenerate triangles next to the tetrahedron
// change no pixel, and no sample is NaN.
TYPED_TEST(TriangleRobust, DegenerateTrianglesInASceneChangeNothing) {
    using T = TypeParam;
    Scene s;
    const int green = add_material(s, "green", material({70, 255, 70}, 0.01, 0.21, 5.5, 79));
    const int metal = add_material(s, "metal", material({70, 70, 70}, 0.01, 0.21, 5.5, 79, true, 0.6));
    for (const auto& f : kFace)
        s.triangles.push_back(
            Triangle<double>::make(kVertex[size_t(f[0])], kVertex[size_t(f[1])], kVertex[size_t(f[2])], green));
    s.planes.push_back({{0, 0, 1}, -1, metal});
    s.ambient_lights.push_back({"a", {255, 255, 255}, 0.002});
    s.directional_lights.push_back({"d", {255, 255, 230}, 0.02, glm::normalize(dvec3(-50, 50, -50))});
    s.spot_lights.push_back({"s", {255, 255, 255}, 2.2, {0, 0, 10}, {0, 0, -1}, 6.283185307179586});
    const Camera cam = camera(Projection::perspective, {-6, -4, 8}, {0, 10, -8}, {0, 0, 1}, 64, 20);
    const auto clean = render(s, cam, precision_of<T>(), all_effects());
    Scene dirty = s;
    std::mt19937_64 rng(6);
    for (const auto& v : degenerate_triangles<T>(rng)) {
        const dvec3 shift(-6, 6, 1);  // into the view
        dirty.triangles.push_back(Triangle<double>::make(v[0] + shift, v[1] + shift, v[2] + shift, metal));
    }
    const auto with = render(dirty, cam, precision_of<T>(), all_effects());
    expect_finite_frame(clean, "tetrahedron");
    expect_finite_frame(with, "tetrahedron and degenerate triangles");
    EXPECT_EQ(count_differing_pixels(clean.image, with.image), 0);
}

}  // namespace
}  // namespace fh
