// A triangle mesh as an object of the scene: its vertices in its own space
// and the transform that places it (scale, then rotate, then translate).
// The scene holds the placed triangles; a mesh a movie moves is placed
// again each frame from here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>

#include "geometry/triangle.h"

namespace fh {

// p -> translate + rotate(scale * p): scale per axis about the origin, then
// a right-handed rotation by `radians` about `axis` through the origin,
// then the move.
struct Transform {
    dvec3 scale{1};
    dvec3 axis{0, 0, 1};  // non-zero; need not be unit
    double radians = 0;
    dvec3 translate{0};

    glm::dmat4 matrix() const;
    bool identity() const { return scale == dvec3(1) && radians == 0 && translate == dvec3(0); }
};

struct Mesh {
    std::vector<dvec3> positions;
    // One per position (from the file; need not be unit), or empty: smooth
    // shading then computes them, area-weighted, from the placed faces.
    std::vector<dvec3> normals;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions
    int material = 0;
    bool smooth = false;  // shade with interpolated vertex normals
    // One texture coordinate (u, v) per position (a glTF TEXCOORD set, its
    // material's KHR_texture_transform applied), or empty.
    std::vector<dvec2> uvs;
    // One colour per position (a glTF COLOR_0, linear, each channel in
    // [0, 1]; a PLY's or OBJ's) multiplying the material's diffuse and
    // ambient colours, or empty.
    std::vector<dvec3> colors;
    // One alpha per position (a glTF COLOR_0 VEC4's, in [0, 1]) multiplying a
    // MASKed material's alpha, or empty (all 1: also when every one is).
    std::vector<double> alphas;
    // One tangent per position (a glTF TANGENT: xyz along increasing u, w
    // the bitangent's sign, +1 or -1), or empty.
    std::vector<glm::dvec4> tangents;
    // No tangents given, but a normal texture needs them: they are made for
    // each triangle's corners from the normals and coordinates, at each
    // pose (scene/mesh_tangents.h). Else a mesh without tangents gives a
    // normal texture each triangle's own (render/normal_map.h).
    bool make_tangents = false;
};

struct PlacedMesh {
    std::vector<Triangle<double>> triangles;  // one per mesh triangle, in order
    // Smooth meshes: each triangle's vertex normals, unit (zero where a
    // vertex has none: its faces cancel out); flat meshes: empty.
    std::vector<std::array<dvec3, 3>> vertex_normals;
};

// The mesh's triangles placed by `transform`. A triangle the transform
// collapses (to within rounding) comes out degenerate (Triangle::make).
PlacedMesh place(const Mesh& mesh, const Transform& transform);
// The same by a matrix (a transform composed with its groups').
PlacedMesh place(const Mesh& mesh, const glm::dmat4& to_world);

}  // namespace fh
