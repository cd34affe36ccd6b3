// Tangents for a mesh that has vertex normals and texture coordinates but
// no tangents of its own (a glTF primitive without TANGENT, whose material
// has a normal texture): at each vertex, the directions of increasing u of
// the triangles around it (dP/du, solved from their edges and coordinates),
// weighted by their areas, made perpendicular to the vertex's normal and
// unit -- so a normal texture turns smoothly across a curved mesh, as
// MikkTSpace's per-vertex tangents do. w, the bitangent's sign, is +1 where
// the triangles around a vertex, by area, map the image the right way round
// (n x t towards the image's up, -dP/dv: glTF's v runs down the image), -1
// where they mirror it.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "scene/mesh.h"

namespace fh {

// One tangent per position (mesh.normals and mesh.uvs one per position).
// A vertex whose triangles give no direction (coordinates on one line,
// directions that cancel, one along its normal) gets (0, 0, 0, 1): the
// normal texture leaves the normal there as it is.
std::vector<glm::dvec4> vertex_tangents(const Mesh& mesh);

}  // namespace fh
