// corner_tangents (scene/mesh_tangents.h): tangents worked out by hand for
// small meshes, u and v laid out as glTF's are (v down the image).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/mesh_tangents.h"

namespace fh {
namespace {

void expect_tangent_near(const glm::dvec4& got, const glm::dvec4& want, const std::string& what) {
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << what << ", component " << k;
}

// Every corner of every triangle.
void expect_every_corner(const Mesh& m, const glm::dvec4& want, const std::string& what) {
    for (const auto& triangle : corner_tangents(m))
        for (const glm::dvec4& t : triangle) expect_tangent_near(t, want, what);
}

// The square [-1, 1]^2 at z = 0, normals up; (u, v) from `uv` at each corner.
Mesh square(const std::vector<dvec2>& uv) {
    Mesh m;
    m.positions = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
    m.normals.assign(4, dvec3(0, 0, 1));
    m.triangles = {{0, 3, 2}, {0, 2, 1}};
    m.uvs = uv;
    return m;
}

TEST(MeshTangents, ASquareMappedTheRightWayRoundAndMirrored) {
    // u along +x, v along -y: t = +x, and n x t = +y is the image's up: w 1.
    expect_every_corner(square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), {1, 0, 0, 1}, "right way round");
    // u along -x: t = -x, n x t = -y runs down the image: w -1.
    expect_every_corner(square({{1, 0}, {0, 0}, {0, 1}, {1, 1}}), {-1, 0, 0, -1}, "mirrored");
    // The image turned a quarter: u along -y, v along -x. t = -y, and
    // n x t = +x = -dP/dv: w 1.
    expect_every_corner(square({{0, 1}, {0, 0}, {1, 0}, {1, 1}}), {0, -1, 0, 1}, "turned");
    // u along -y, v along +x: mirrored, w -1.
    expect_every_corner(square({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), {0, -1, 0, -1}, "turned and mirrored");
}

TEST(MeshTangents, ARidgeAveragesItsTwoSlopesByArea) {
    // A ridge along y from A (0, -1, 0) to B (0, 1, 0), slopes down to
    // L (-1, 0, -1) and R (1, 0, -1); u = x, v = -y. Along the left slope
    // dP/du = (1, 0, 1), along the right (1, 0, -1); the areas are equal.
    // A and B (normal up): the sum (2, 0, 0), t = +x in both triangles. L
    // and R, with their slopes' normals: t = (1, 0, 1) / sqrt 2 and
    // (1, 0, -1) / sqrt 2.
    Mesh m;
    m.positions = {{0, -1, 0}, {0, 1, 0}, {-1, 0, -1}, {1, 0, -1}};
    m.uvs = {{0, 1}, {0, -1}, {-1, 0}, {1, 0}};
    const double h = std::sqrt(0.5);
    m.normals = {{0, 0, 1}, {0, 0, 1}, {-h, 0, h}, {h, 0, h}};
    m.triangles = {{0, 1, 2}, {0, 3, 1}};
    const auto t = corner_tangents(m);
    for (const size_t k : {size_t(0), size_t(1)}) {
        expect_tangent_near(t[k][0], {1, 0, 0, 1}, "A");
        expect_tangent_near(t[k][k == 0 ? 1 : 2], {1, 0, 0, 1}, "B");
    }
    expect_tangent_near(t[0][2], {h, 0, h, 1}, "L");
    expect_tangent_near(t[1][1], {h, 0, -h, 1}, "R");
}

TEST(MeshTangents, AMirrorSeamServesEachSideWithItsOwn) {
    // Two triangles sharing (0, 0, 0) and (0, 1, 0), mapped the two ways
    // round: u = x in (0, 0, 0), (1, 0, 0), (0, 1, 0), u = -x in (0, 0, 0),
    // (0, 1, 0), (-1, 0, 0), v = -y in both -- a symmetric model's middle,
    // its seam's vertices shared. Each triangle's corners keep its own
    // direction and sign, the shared ones too: summed, they would cancel.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    m.uvs = {{0, 0}, {1, 0}, {0, -1}, {1, 0}};
    m.normals.assign(4, dvec3(0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    const auto t = corner_tangents(m);
    for (int c = 0; c < 3; ++c) {
        expect_tangent_near(t[0][size_t(c)], {1, 0, 0, 1}, "the right way round, corner " + std::to_string(c));
        expect_tangent_near(t[1][size_t(c)], {-1, 0, 0, -1}, "mirrored, corner " + std::to_string(c));
    }
}

TEST(MeshTangents, NoDirectionGivesAZeroTangent) {
    // Every corner at the same (u, v): no triangle gives a direction.
    expect_every_corner(square({{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}}), {0, 0, 0, 1}, "one point");
    // u along the ridge's normal at A: a direction along the normal is none.
    Mesh m = square({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    m.normals[0] = {1, 0, 0};
    expect_tangent_near(corner_tangents(m)[0][0], {0, 0, 0, 1}, "along the normal");
}

}  // namespace
}  // namespace fh
