#include "scene/deformation.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "scene/node.h"
#include "scene/scene.h"

namespace fh {

namespace {

// A normal's matrix: the inverse transpose of m's linear part, or the part
// itself where it has no inverse (a joint scaled to nothing).
glm::dmat3 normal_matrix(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    const double det = glm::determinant(a);
    return det != 0 && std::isfinite(det) ? glm::inverseTranspose(a) : a;
}

}  // namespace

Mesh deformed(const Deformation& d, const std::vector<double>& weights, const std::vector<glm::dmat4>& joint_matrices) {
    Mesh m = *d.rest;
    const size_t targets = d.targets ? d.targets->size() : 0;
    for (size_t t = 0; t < targets && t < weights.size(); ++t) {
        const double w = weights[t];
        if (w == 0) continue;
        const MorphTarget& target = (*d.targets)[t];
        for (size_t v = 0; v < m.positions.size(); ++v) m.positions[v] += w * target.positions[v];
        if (!target.normals.empty() && !m.normals.empty())
            for (size_t v = 0; v < m.normals.size(); ++v) m.normals[v] += w * target.normals[v];
        if (!target.tangents.empty() && !m.tangents.empty())
            for (size_t v = 0; v < m.tangents.size(); ++v) m.tangents[v] += glm::dvec4(w * target.tangents[v], 0.0);
    }
    if (d.skin.weights) {
        const SkinWeights& s = *d.skin.weights;
        const size_t k = size_t(s.influences);
        for (size_t v = 0; v < m.positions.size(); ++v) {
            glm::dmat4 blend(0.0);
            for (size_t i = 0; i < k; ++i)
                if (const double w = s.weight[v * k + i]; w != 0) blend += w * joint_matrices[s.joint[v * k + i]];
            m.positions[v] = dvec3(blend * glm::dvec4(m.positions[v], 1.0));
            if (!m.normals.empty()) m.normals[v] = normal_matrix(blend) * m.normals[v];
            // A tangent lies in the surface: it moves as its edges do; a
            // mirroring blend turns its bitangent's sign too.
            if (!m.tangents.empty()) {
                const glm::dmat3 a(blend);
                m.tangents[v] = glm::dvec4(a * dvec3(m.tangents[v]), glm::determinant(a) < 0 ? -m.tangents[v].w
                                                                                          : m.tangents[v].w);
            }
        }
    }
    return m;
}

void deform_meshes(Scene& scene) {
    if (scene.deformations.empty()) return;
    const std::vector<glm::dmat4> world = node_matrices(scene);
    std::vector<glm::dmat4> joints;
    for (const Deformation& d : scene.deformations) {
        joints.clear();
        if (d.skin.weights) {
            const glm::dmat4& n = world[size_t(d.node)];
            // A node scaled to nothing shows nothing: its mesh collapses
            // (and its triangles, degenerate, are left out).
            const double det = glm::determinant(glm::dmat3(n));
            const glm::dmat4 to_node = det != 0 && std::isfinite(det) ? glm::inverse(n) : glm::dmat4(0.0);
            for (size_t j = 0; j < d.skin.joints.size(); ++j)
                joints.push_back(to_node * world[size_t(d.skin.joints[j])] * d.skin.inverse_binds[j]);
        }
        scene.meshes[size_t(d.mesh)].mesh =
            std::make_shared<const Mesh>(deformed(d, scene.nodes[size_t(d.node)].weights, joints));
    }
}

}  // namespace fh
