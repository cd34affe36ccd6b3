// Tangents for a mesh that has vertex normals and texture coordinates but
// no tangents of its own (a glTF primitive without TANGENT, whose material
// has a normal texture): at each corner of a triangle, the directions of
// increasing u (dP/du, solved from their edges and coordinates) of the
// triangles around that vertex that map the image the same way round as
// this one, weighted by their areas, made perpendicular to the vertex's
// normal and unit -- so a normal texture turns smoothly across a curved
// mesh, as MikkTSpace's per-vertex tangents do, and a vertex on a mirror
// seam (a symmetric model's middle) serves each side with its own. w, the
// bitangent's sign, is the triangle's: +1 where n x t points to the image's
// up (-dP/dv: glTF's v runs down the image), -1 where it is mirrored.
#pragma once

#include <array>
#include <vector>

#include <glm/vec4.hpp>

#include "scene/mesh.h"

namespace fh {

// One tangent per corner of each of mesh.triangles (mesh.normals and
// mesh.uvs one per position). A triangle whose coordinates do not span it
// (on one line) gets (0, 0, 0, 1) at its corners, and so does a corner
// whose directions cancel or lie along its normal: the normal texture
// leaves the normal there as it is.
std::vector<std::array<glm::dvec4, 3>> corner_tangents(const Mesh& mesh);

}  // namespace fh
