// The two-level walk (render/instance_walk.h) against brute force: every
// instance entered by the same transform of the rays, every triangle of its
// mesh tested, the nearest kept by the documented tie rule -- the same hit
// (t, instance, primitive) to the bit, for a million random rays in float and
// in double (a quarter under the sanitizers), over instances turned, scaled
// unevenly and mirrored; shadow rays blocked exactly when brute force finds a
// blocker; and no ray aimed at an instanced closed mesh's vertices and edges
// slipping through it.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/icosphere.h"
#include "render/instance_walk.h"
#include "sanitizer_build.h"

namespace fh {
namespace {

template <typename T>
class InstanceWalk : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(InstanceWalk, Scalars);

// A closed mesh (the icosphere of 80 triangles, radius 1) in its own space.
std::shared_ptr<const Mesh> sphere_mesh(int subdivisions = 1) {
    auto mesh = std::make_shared<Mesh>();
    for (const Triangle<double>& t : icosphere(subdivisions, 1.0, 0)) {
        const auto n = std::uint32_t(mesh->positions.size());
        mesh->positions.insert(mesh->positions.end(), {t.v0, t.v1, t.v2});
        mesh->triangles.push_back({n, n + 1, n + 2});
    }
    return mesh;
}

// A closed box of 12 triangles: few enough that its mesh is tested as a
// list, its leaves listing their triangles rather than running over them.
std::shared_ptr<const Mesh> box_mesh() {
    auto mesh = std::make_shared<Mesh>();
    for (int i = 0; i < 8; ++i) mesh->positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        mesh->triangles.push_back({f[0], f[1], f[2]});
        mesh->triangles.push_back({f[0], f[2], f[3]});
    }
    return mesh;
}

// A random placement: turned about a random axis, scaled unevenly by 0.3 .. 2
// per axis, mirrored when `mirror`, moved within 8 of the origin.
glm::dmat4 random_placement(std::mt19937& rng, bool mirror) {
    std::uniform_real_distribution<double> u(-1, 1), s(0.3, 2);
    dvec3 axis(u(rng), u(rng), u(rng));
    if (glm::length(axis) < 1e-3) axis = {0, 0, 1};
    Transform t;
    t.axis = axis;
    t.radians = 3.14159 * u(rng);
    t.scale = {s(rng), s(rng), s(rng)};
    if (mirror) t.scale.y = -t.scale.y;
    t.translate = 8.0 * dvec3(u(rng), u(rng), u(rng));
    return t.matrix();
}

// A world of a plane, two spheres and a loose triangle, and `count` instances
// of `mesh` (every third mirrored).
Scene instanced_scene(std::mt19937& rng, int count, std::shared_ptr<const Mesh> mesh) {
    Scene s;
    s.materials.resize(3);
    s.planes.push_back({{0, 0, 1}, -12, 0});
    s.spheres().push_back({{2, 1, 0}, 1.5, 1});
    s.spheres().push_back({{-5, 3, 2}, 0.7, 1});
    s.triangles.push_back(Triangle<double>::make({-3, -3, 0}, {3, -3, 0}, {0, 3, 1}, 2));
    s.meshes.push_back({"ball", std::move(mesh)});
    for (int i = 0; i < count; ++i) s.instances.push_back({0, 2, random_placement(rng, i % 3 == 0)});
    return s;
}

template <typename T>
struct TwoLevels {
    FlatGeometry<T> world;
    std::shared_ptr<const InstanceSet<T>> instances;
    explicit TwoLevels(const Scene& s) : world(FlatGeometry<T>::build(s)), instances(InstanceSet<T>::build(s)) {}
};

// Brute force, lane by lane of the packet: the world's nearest hit as its own
// walk finds it, then every instance's every triangle in that instance's
// space, the instance's nearest (t, id) carried to the world as t / scale.
template <typename T>
void brute_force(const TwoLevels<T>& g, const RayPacket<T>& ray, const LaneInts<T>& active, Lanes<T>& t,
                 LaneInts<T>& prim, LaneInts<T>& instance) {
    const HitLanes<T> world = closest_hits(g.world, ray, active);
    t = world.t;
    prim = world.prim;
    instance = LaneInts<T>{} + kNoInstance;
    for (size_t i = 0; i < g.instances->instances.size(); ++i) {
        const FlatInstance<T>& in = g.instances->instances[i];
        const FlatGeometry<T>& mesh = *g.instances->meshes[size_t(in.mesh)];
        Lanes<T> scale;
        const RayPacket<T> local = in.enter(ray, scale);
        const RayBasis<T> basis(local);
        Lanes<T> nearest = splat(kInfinity<T>);
        LaneInts<T> nearest_id = LaneInts<T>{} + kNoHit;
        for (int k = 0; k < mesh.ids.triangles; ++k) {
            const Lanes<T> tk = mesh.triangles[size_t(k)].intersect(basis, T(0), splat(kInfinity<T>));
            const int id = mesh.ids.triangle(k);
            const LaneInts<T> nearer = (tk < nearest) | ((tk == nearest) & (nearest_id > id));
            nearest = select(nearer, tk, nearest);
            nearest_id = select(nearer, LaneInts<T>{} + id, nearest_id);
        }
        const Lanes<T> tw = nearest / scale;
        const LaneInts<T> nearer = active & (nearest_id != kNoHit) & ((tw < t) | ((tw == t) & (instance > int(i))));
        t = select(nearer, tw, t);
        prim = select(nearer, nearest_id, prim);
        instance = select(nearer, LaneInts<T>{} + int(i), instance);
    }
}

// Random rays: half from anywhere in a box toward anywhere, half aimed at a
// random instance's centre (so most packets meet instances).
template <typename T>
RayPacket<T> random_instanced_packet(std::mt19937& rng, const Scene& s) {
    std::uniform_real_distribution<double> u(-14, 14), small(-1, 1);
    RayPacket<T> p;
    for (int lane = 0; lane < kLanes<T>; ++lane) {
        const dvec3 o(u(rng), u(rng), u(rng));
        dvec3 to(u(rng), u(rng), u(rng));
        if (lane % 2 == 0) {
            const glm::dmat4& m = s.instances[size_t(rng() % s.instances.size())].to_world;
            to = dvec3(m * glm::dvec4(small(rng), small(rng), small(rng), 1.0));
        }
        const Vec3<T> d = Vec3<T>(glm::normalize(to - o));
        for (int c = 0; c < 3; ++c) {
            (c == 0 ? p.origin.x : c == 1 ? p.origin.y : p.origin.z)[lane] = T(o[c]);
            (c == 0 ? p.direction.x : c == 1 ? p.direction.y : p.direction.z)[lane] = d[c];
        }
    }
    return p;
}

// The two-level walk's hits of every lane of a packet, asserted equal to
// brute force's (packet n, for messages); returns each lane's instance.
template <typename T>
LaneInts<T> expect_brute_force(const TwoLevels<T>& g, const RayPacket<T>& ray, int n) {
    const LaneInts<T> all = first_lanes<T>(kLanes<T>);
    LaneInts<T> instance;
    const HitLanes<T> h = closest_hits(g.world, g.instances.get(), ray, all, instance);
    Lanes<T> bt;
    LaneInts<T> bp, bi;
    brute_force(g, ray, all, bt, bp, bi);
    for (int lane = 0; lane < kLanes<T>; ++lane) {
        EXPECT_EQ(h.prim[lane], bp[lane]) << "ray " << n << " lane " << lane;
        EXPECT_EQ(instance[lane], bi[lane]) << "ray " << n << " lane " << lane;
        if (bp[lane] != kNoHit) EXPECT_EQ(h.t[lane], bt[lane]) << "ray " << n << " lane " << lane;
        if (::testing::Test::HasFailure()) return instance;
    }
    return instance;
}

TYPED_TEST(InstanceWalk, NearestHitIsBruteForcesForAMillionRays) {
    using T = TypeParam;
    std::mt19937 rng(7);
    const Scene scene = instanced_scene(rng, 9, sphere_mesh());
    const TwoLevels<T> g(scene);
    // A quarter of the rays under the sanitizers, which run it 10-20x slower.
    const int rays = kSanitized ? 250'000 : 1'000'000;
    long hits_on_instances = 0, checked = 0;
    for (int n = 0; n < rays / kLanes<T>; ++n) {
        const LaneInts<T> on = expect_brute_force(g, random_instanced_packet<T>(rng, scene), n);
        if (::testing::Test::HasFailure()) return;  // the first difference is enough
        checked += kLanes<T>;
        hits_on_instances += count(on >= 0);
    }
    EXPECT_EQ(checked, rays / kLanes<T> * kLanes<T>);
    EXPECT_GT(hits_on_instances, checked / 4);  // the test reaches the second level
}

TYPED_TEST(InstanceWalk, NearestHitIsBruteForcesForASmallMesh) {
    using T = TypeParam;
    std::mt19937 rng(13);
    const Scene scene = instanced_scene(rng, 9, box_mesh());
    const TwoLevels<T> g(scene);
    long hits_on_instances = 0;
    for (int n = 0; n < 100'000 / kLanes<T>; ++n) {
        const LaneInts<T> on = expect_brute_force(g, random_instanced_packet<T>(rng, scene), n);
        if (::testing::Test::HasFailure()) return;  // the first difference is enough
        hits_on_instances += count(on >= 0);
    }
    EXPECT_GT(hits_on_instances, 10'000);
}

TYPED_TEST(InstanceWalk, ShadowRaysAreBlockedExactlyWhenBruteForceFindsABlocker) {
    using T = TypeParam;
    std::mt19937 rng(11);
    const Scene scene = instanced_scene(rng, 9, sphere_mesh());
    const TwoLevels<T> g(scene);
    const LaneInts<T> all = first_lanes<T>(kLanes<T>);
    std::uniform_real_distribution<T> reach(0.5, 30);
    long blocked_by_instances = 0;
    for (int n = 0; n < 200'000 / kLanes<T>; ++n) {
        const RayPacket<T> ray = random_instanced_packet<T>(rng, scene);
        Lanes<T> t_max;
        for (int lane = 0; lane < kLanes<T>; ++lane) t_max[lane] = reach(rng);
        const LaneInts<T> blocked = occluded(g.world, g.instances.get(), ray, t_max, all);
        // Brute force: the world's own answer, or any instance's triangle
        // nearer than t_max (in its space: t_max * scale).
        LaneInts<T> expected = occluded(g.world, ray, t_max, all);
        LaneInts<T> by_instance{};
        for (const FlatInstance<T>& in : g.instances->instances) {
            Lanes<T> scale;
            const RayPacket<T> local = in.enter(ray, scale);
            const RayBasis<T> basis(local);
            const FlatGeometry<T>& mesh = *g.instances->meshes[size_t(in.mesh)];
            for (const Triangle<T>& tri : mesh.triangles)
                by_instance |= tri.intersect(basis, T(0), t_max * scale) < kInfinity<T>;
        }
        blocked_by_instances += count(by_instance & ~expected);
        expected |= by_instance;
        for (int lane = 0; lane < kLanes<T>; ++lane)
            ASSERT_EQ(blocked[lane] != 0, expected[lane] != 0) << "ray " << n << " lane " << lane;
    }
    EXPECT_GT(blocked_by_instances, 10'000);
}

// Ties: three copies of one placement hit at the same distance, whatever
// order the walk visits them in; the first copy wins, as brute force says.
TYPED_TEST(InstanceWalk, CoincidentInstancesGoToTheFirst) {
    using T = TypeParam;
    std::mt19937 rng(5);
    Scene scene = instanced_scene(rng, 4, sphere_mesh());
    for (int copy = 0; copy < 3; ++copy) scene.instances.push_back(scene.instances[size_t(copy)]);
    std::swap(scene.instances[0], scene.instances[5]);  // a copy before its original
    const TwoLevels<T> g(scene);
    long ties = 0;
    for (int n = 0; n < 50'000 / kLanes<T>; ++n) {
        const LaneInts<T> on = expect_brute_force(g, random_instanced_packet<T>(rng, scene), n);
        if (::testing::Test::HasFailure()) return;  // the first difference is enough
        ties += count((on >= 0) & ((on < 3) | (on == 5)));
    }
    EXPECT_GT(ties, 1000);
}

// Rays from outside at every vertex and along every edge of a closed mesh,
// instanced turned, scaled unevenly and mirrored: each must hit it, traced
// alone and as lanes of packets (each walk has its own code).
TYPED_TEST(InstanceWalk, NoRayLeaksThroughAClosedMeshUnderAnyInstance) {
    using T = TypeParam;
    std::mt19937 rng(3);
    const auto mesh = sphere_mesh(2);  // 320 triangles
    Scene scene;
    scene.materials.resize(1);
    scene.meshes.push_back({"ball", mesh});
    for (int i = 0; i < 6; ++i) scene.instances.push_back({0, 0, random_placement(rng, i % 2 == 1)});
    const TwoLevels<T> g(scene);
    std::vector<Ray<T>> rays;
    std::uniform_real_distribution<double> far(5, 40), wobble(-0.5, 0.5);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const glm::dmat4& m = scene.instances[i].to_world;
        const glm::dmat3 normals = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (const auto& tri : mesh->triangles)
            for (int corner = 0; corner < 3; ++corner)
                for (const double along : {0.0, 0.25, 0.5, 1.0 / 3.0}) {
                    // A vertex, or a point of the edge to the next corner.
                    const dvec3 a = mesh->positions[tri[size_t(corner)]], b = mesh->positions[tri[size_t((corner + 1) % 3)]];
                    const dvec3 p = a + along * (b - a);
                    const dvec3 target = dvec3(m * glm::dvec4(p, 1.0));
                    // From outside, roughly along the outward normal there
                    // (the sphere's is p itself), never grazing.
                    const dvec3 out = glm::normalize(normals * p) + 0.3 * dvec3(wobble(rng), wobble(rng), wobble(rng));
                    const dvec3 origin = target + far(rng) * glm::normalize(out);
                    rays.push_back({Vec3<T>(origin), Vec3<T>(glm::normalize(target - origin))});
                }
    }
    long leaks = 0, packet_leaks = 0;
    for (const Ray<T>& ray : rays) leaks += !closest_hit(g.world, g.instances.get(), ray).found();
    // The same rays kLanes at a time: neighbours in the list aim at one
    // triangle's corners from different sides, so the packets are incoherent.
    const int lanes = kLanes<T>;
    const size_t whole = rays.size() / size_t(lanes) * size_t(lanes);
    for (size_t first = 0; first < whole; first += size_t(lanes)) {
        RayPacket<T> p;
        for (int lane = 0; lane < lanes; ++lane) {
            const Ray<T>& r = rays[first + size_t(lane)];
            p.origin.x[lane] = r.origin.x, p.origin.y[lane] = r.origin.y, p.origin.z[lane] = r.origin.z;
            p.direction.x[lane] = r.direction.x, p.direction.y[lane] = r.direction.y, p.direction.z[lane] = r.direction.z;
        }
        LaneInts<T> instance;
        const HitLanes<T> h = closest_hits(g.world, g.instances.get(), p, first_lanes<T>(lanes), instance);
        for (int lane = 0; lane < lanes; ++lane) packet_leaks += h.prim[lane] == kNoHit;
    }
    EXPECT_GT(rays.size(), 20'000u);
    EXPECT_EQ(leaks, 0) << "of " << rays.size() << " rays traced alone";
    EXPECT_EQ(packet_leaks, 0) << "of " << whole << " rays traced in packets";
}

// A movie's frame where no instance moved keeps the previous frame's set, its
// top BVH not refitted; one instance moved gives a new set with that
// instance's maps and box, the others' to the bit.
TYPED_TEST(InstanceWalk, AFrameWhereNothingMovedKeepsTheInstances) {
    using T = TypeParam;
    std::mt19937 rng(5);
    Scene scene = instanced_scene(rng, 20, sphere_mesh());
    const auto first = InstanceSet<T>::build(scene);
    EXPECT_EQ(InstanceSet<T>::moved(first, scene), first);
    scene.instances[7].to_world = glm::translate(glm::dmat4(1.0), {100, 0, 0}) * scene.instances[7].to_world;
    const auto second = InstanceSet<T>::moved(first, scene);
    ASSERT_NE(second, first);
    ASSERT_EQ(second->instances.size(), first->instances.size());
    for (size_t k = 0; k < first->instances.size(); ++k) {
        const FlatInstance<T>&a = second->instances[k], &b = first->instances[k];
        EXPECT_EQ(std::memcmp(&a.to_object, &b.to_object, 3 * sizeof(AffineMap<T>)) == 0, k != 7) << k;
    }
    EXPECT_GT(second->bvh.nodes.front().hi[0], 90.0f);  // the root box reaches the moved instance
    EXPECT_LT(first->bvh.nodes.front().hi[0], 20.0f);
    EXPECT_EQ(InstanceSet<T>::moved(second, scene), second);
}

// A mirrored instance's hit points and normals, as shading finds them,
// against the same triangle placed in the world by hand.
TYPED_TEST(InstanceWalk, AMirroredInstancesHitIsTheWorldTrianglesHit) {
    using T = TypeParam;
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    Scene scene;
    scene.materials.resize(1);
    scene.meshes.push_back({"tri", mesh});
    // Mirror x, then move up 2: the triangle (0,0,2) (-1,0,2) (0,1,2).
    const glm::dmat4 m = glm::scale(glm::translate(glm::dmat4(1.0), {0, 0, 2}), {-1, 1, 1});
    scene.instances.push_back({0, 0, m});
    const TwoLevels<T> g(scene);
    const Ray<T> down{{T(-0.25), T(0.25), 5}, {0, 0, -1}};
    const Hit<T> h = closest_hit(g.world, g.instances.get(), down);
    ASSERT_TRUE(h.found());
    EXPECT_EQ(h.instance, 0);
    EXPECT_EQ(h.t, T(3));
    // Beside it, where the unmirrored triangle would be: nothing.
    EXPECT_FALSE(closest_hit(g.world, g.instances.get(), Ray<T>{{T(0.25), T(0.25), 5}, {0, 0, -1}}).found());
}

}  // namespace
}  // namespace fh
