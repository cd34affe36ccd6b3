#include "scene/mesh_tangents.h"

#include <cmath>

namespace fh {

namespace {

// A triangle's dP/du and whether its coordinates are mirrored against its
// first vertex's normal (the three share a side of the mesh); false where
// its coordinates do not span it.
bool frame_of(const Mesh& mesh, const std::array<std::uint32_t, 3>& t, dvec3& du, double& area, bool& mirrored) {
    const dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]], e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
    const dvec2 d1 = mesh.uvs[t[1]] - mesh.uvs[t[0]], d2 = mesh.uvs[t[2]] - mesh.uvs[t[0]];
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (!(det != 0) || !std::isfinite(det)) return false;
    du = (d2.y * e1 - d1.y * e2) / det;
    const dvec3 dv = (d1.x * e2 - d2.x * e1) / det;
    area = 0.5 * glm::length(glm::cross(e1, e2));
    const double length = glm::length(du);
    if (!(area > 0) || !(length > 0) || !std::isfinite(area + length)) return false;
    du *= area / length;  // unit, weighted by area
    const dvec3 n = mesh.normals[t[0]] + mesh.normals[t[1]] + mesh.normals[t[2]];
    mirrored = glm::dot(glm::cross(n, du), dv) > 0;
    return true;
}

}  // namespace

std::vector<std::array<glm::dvec4, 3>> corner_tangents(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    // Per vertex, the sums of the triangles mapped the right way round ([0])
    // and mirrored ([1]).
    std::vector<std::array<dvec3, 2>> along(n, {dvec3(0), dvec3(0)});
    std::vector<signed char> side(mesh.triangles.size(), -1);  // 0, 1, or -1: no frame
    for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& t = mesh.triangles[k];
        dvec3 du;
        double area;
        bool mirrored;
        if (!frame_of(mesh, t, du, area, mirrored)) continue;
        side[k] = mirrored ? 1 : 0;
        for (const std::uint32_t v : t) along[v][size_t(side[k])] += du;
    }
    std::vector<std::array<glm::dvec4, 3>> out(mesh.triangles.size());
    for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
            glm::dvec4& corner = out[k][size_t(c)];
            corner = glm::dvec4(0, 0, 0, 1);
            if (side[k] < 0) continue;
            corner.w = side[k] == 1 ? -1.0 : 1.0;
            const std::uint32_t v = mesh.triangles[k][size_t(c)];
            const dvec3 normal = mesh.normals[v], a = along[v][size_t(side[k])];
            const double normal2 = glm::dot(normal, normal);
            if (!(normal2 > 0) || !std::isfinite(normal2)) continue;
            const dvec3 t = a - (glm::dot(normal, a) / normal2) * normal;
            const double length = glm::length(t);
            // Directions that (nearly) cancel, or lie along the normal, give none.
            if (!(length > 1e-9 * glm::length(a)) || !std::isfinite(length)) continue;
            corner = glm::dvec4(t / length, corner.w);
        }
    }
    return out;
}

}  // namespace fh
