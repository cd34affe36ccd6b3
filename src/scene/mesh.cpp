#include "scene/mesh.h"

#include <glm/gtc/matrix_transform.hpp>

namespace fh {

glm::dmat4 Transform::matrix() const {
    glm::dmat4 t = glm::translate(glm::dmat4(1.0), translate);
    const dvec3 a = axis / max_abs_component(axis);  // no overflow in the length
    if (radians != 0) t = glm::rotate(t, radians, glm::normalize(a));
    return glm::scale(t, scale);
}

PlacedMesh place(const Mesh& mesh, const Transform& transform) { return place(mesh, transform.matrix()); }

PlacedMesh place(const Mesh& mesh, const glm::dmat4& m) {
    const bool identity = m == glm::dmat4(1.0);
    std::vector<dvec3> p(mesh.positions.size());
    for (size_t i = 0; i < p.size(); ++i)
        p[i] = identity ? mesh.positions[i] : dvec3(m * glm::dvec4(mesh.positions[i], 1.0));
    PlacedMesh out;
    out.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        out.triangles.push_back(Triangle<double>::make(p[t[0]], p[t[1]], p[t[2]], mesh.material));
    if (!mesh.smooth) return out;

    std::vector<dvec3> n(p.size(), dvec3(0));
    if (!mesh.normals.empty()) {
        // Normals move by the inverse transpose: a per-axis scale bends them.
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
        for (size_t i = 0; i < n.size(); ++i) n[i] = unit_or_zero(normal_matrix * mesh.normals[i]);
    } else {
        // Area-weighted: the cross product's length is twice the face's area.
        for (const auto& t : mesh.triangles) {
            const dvec3 c = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
            for (const std::uint32_t v : t) n[v] += c;
        }
        for (dvec3& v : n) v = unit_or_zero(v);
    }
    out.vertex_normals.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) out.vertex_normals.push_back({n[t[0]], n[t[1]], n[t[2]]});
    return out;
}

}  // namespace fh
