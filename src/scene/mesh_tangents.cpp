#include "scene/mesh_tangents.h"

#include <cmath>

namespace fh {

std::vector<glm::dvec4> vertex_tangents(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<dvec3> along(n, dvec3(0));
    std::vector<double> handedness(n, 0);
    for (const auto& t : mesh.triangles) {
        const dvec3 e1 = mesh.positions[t[1]] - mesh.positions[t[0]], e2 = mesh.positions[t[2]] - mesh.positions[t[0]];
        const dvec2 d1 = mesh.uvs[t[1]] - mesh.uvs[t[0]], d2 = mesh.uvs[t[2]] - mesh.uvs[t[0]];
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (!(det != 0) || !std::isfinite(det)) continue;  // coordinates on one line
        const dvec3 du = (d2.y * e1 - d1.y * e2) / det, dv = (d1.x * e2 - d2.x * e1) / det;
        const double area = 0.5 * glm::length(glm::cross(e1, e2)), length = glm::length(du);
        if (!(area > 0) || !(length > 0) || !std::isfinite(area + length)) continue;
        for (const std::uint32_t v : t) {
            along[v] += (area / length) * du;
            handedness[v] += glm::dot(glm::cross(mesh.normals[v], du), dv) > 0 ? -area : area;
        }
    }
    std::vector<glm::dvec4> out(n, glm::dvec4(0, 0, 0, 1));
    for (size_t v = 0; v < n; ++v) {
        const dvec3 normal = mesh.normals[v];
        const double normal2 = glm::dot(normal, normal);
        if (!(normal2 > 0) || !std::isfinite(normal2)) continue;
        const dvec3 t = along[v] - (glm::dot(normal, along[v]) / normal2) * normal;
        const double length = glm::length(t);
        // Directions that (nearly) cancel, or lie along the normal, give none.
        if (!(length > 1e-9 * glm::length(along[v])) || !std::isfinite(length)) continue;
        out[v] = glm::dvec4(t / length, handedness[v] < 0 ? -1.0 : 1.0);
    }
    return out;
}

}  // namespace fh
