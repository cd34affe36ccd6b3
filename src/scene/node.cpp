#include "scene/node.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace fh {

glm::dmat4 SceneNode::local() const {
    if (has_matrix) return matrix;
    // T * R * S, the glTF order.
    return glm::scale(glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation), scale);
}

std::vector<glm::dmat4> node_matrices(const Scene& scene) {
    const std::vector<glm::dmat4> groups = group_matrices(scene.groups);
    std::vector<glm::dmat4> world(scene.nodes.size());
    for (size_t n = 0; n < scene.nodes.size(); ++n) {
        const SceneNode& node = scene.nodes[n];
        const glm::dmat4 above = node.parent >= 0 ? world[size_t(node.parent)]
                                 : node.group >= 0 ? groups[size_t(node.group)]
                                                   : glm::dmat4(1.0);
        world[n] = above * node.local();
    }
    return world;
}

void place_nodes(Scene& scene) {
    if (scene.nodes.empty()) return;
    const std::vector<glm::dmat4> world = node_matrices(scene);
    // A product of finite animated values can overflow (a scale of 1e200
    // under another), or pass what the float tracer carries (1e-12..1e12):
    // such an instance shows nothing, as a scale of 0, and such a camera or
    // light stays where it last was.
    for (Instance& i : scene.instances) {
        if (i.node < 0) continue;
        const glm::dmat4 m = i.row < 0 ? world[size_t(i.node)] : world[size_t(i.node)] * scene.instance_rows[size_t(i.row)];
        i.to_world = usable_or_nothing(m);
    }
    auto origin = [&](int n) { return dvec3(world[size_t(n)][3]); };
    auto axis = [&](int n, const dvec3& a) { return dvec3(glm::dmat3(world[size_t(n)]) * a); };
    auto placed = [&](int n) { return n >= 0 && is_finite(world[size_t(n)]); };
    for (Camera& c : scene.cameras) {
        if (!placed(c.node)) continue;
        c.view_point = origin(c.node);
        c.look_at = axis(c.node, {0, 0, -1});
        c.up = axis(c.node, {0, 1, 0});
    }
    for (auto& l : scene.directional_lights)
        if (placed(l.node)) l.direction = unit_or_zero(axis(l.node, {0, 0, -1}));
    for (auto& l : scene.spot_lights) {
        if (!placed(l.node)) continue;
        l.position = origin(l.node);
        l.axis = unit_or_zero(axis(l.node, {0, 0, -1}));
    }
}

}  // namespace fh
