#include "gltf/gltf_nodes.h"

#include <cmath>
#include <cstdio>
#include <functional>

#include "scene/instance.h"
#include "text/input_error.h"

namespace fh {

GltfNodeOrder order_gltf_nodes(const tinygltf::Model& m_, const std::string& file) {
    auto fail = [&](const std::string& what) { throw InputError(file, what); };
    GltfNodeOrder out;
    const size_t n = m_.nodes.size();
    std::vector<int> parent(n, -1);
    for (size_t p = 0; p < n; ++p)
        for (const int c : m_.nodes[p].children) {
            if (c < 0 || size_t(c) >= n) fail("node " + std::to_string(p) + " has child " + std::to_string(c) + ", which does not exist");
            if (parent[size_t(c)] >= 0)
                fail("node " + std::to_string(c) + " has two parents (" + std::to_string(parent[size_t(c)]) +
                     " and " + std::to_string(p) + ")");
            parent[size_t(c)] = int(p);
        }
    // One parent each, so a cycle is a loop of parents, found anywhere in
    // the file (shown or not): follow each node's parents until a node
    // already followed; one met again on this same walk closes a loop.
    std::vector<int> walked_from(n, -1);
    for (size_t start = 0; start < n; ++start) {
        int x = int(start);
        while (x >= 0 && walked_from[size_t(x)] < 0) {
            walked_from[size_t(x)] = int(start);
            x = parent[size_t(x)];
        }
        if (x >= 0 && walked_from[size_t(x)] == int(start))
            fail("node " + std::to_string(x) + " is its own ancestor (a cycle)");
    }
    std::vector<int> roots;
    if (m_.scenes.empty()) fail("the file has no scene to show (no 'scenes')");
    int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (size_t(scene) >= m_.scenes.size()) fail("scene " + std::to_string(scene) + " does not exist");
    roots = m_.scenes[size_t(scene)].nodes;
    if (roots.empty()) fail("scene " + std::to_string(scene) + " has no nodes: nothing to show");
    out.new_index.assign(n, -1);
    std::vector<int> state(n, 0);  // 0 unseen, 1 on the path, 2 done (cycles are refused above)
    std::function<void(int, int)> visit = [&](int node, int depth) {
        if (node < 0 || size_t(node) >= n) fail("scene node " + std::to_string(node) + " does not exist");
        if (state[size_t(node)] == 2) fail("node " + std::to_string(node) + " is reached twice");
        if (depth > 10'000) fail("nodes nested more than 10,000 deep");
        state[size_t(node)] = 1;
        out.new_index[size_t(node)] = int(out.order.size());
        out.order.push_back(node);
        for (const int c : m_.nodes[size_t(node)].children) visit(c, depth + 1);
        state[size_t(node)] = 2;
    };
    for (const int r : roots) {
        if (r >= 0 && size_t(r) < n && parent[size_t(r)] >= 0)
            fail("scene node " + std::to_string(r) + " is also a child of node " + std::to_string(parent[size_t(r)]));
        visit(r, 0);
    }
    out.parent = std::move(parent);
    return out;
}

namespace {

// glTF's rotations are unit quaternions (x, y, z, w). Exporters round, so a
// near-unit one is normalized; one near zero has no direction to normalize
// to (glm would make it the identity without a word), so it is refused.
template <typename Fail>
glm::dquat unit_rotation(const double* xyzw, const std::string& what, Fail&& fail) {
    const glm::dquat q(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
    const double length = glm::length(q);
    if (!(length >= 1e-6)) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", length);
        fail(what + " is not a rotation (a quaternion of length " + text + "; glTF's are of length 1)");
    }
    return glm::normalize(q);  // as before this check: the same bits
}

}  // namespace

SceneNode gltf_scene_node(const tinygltf::Node& node, int index, const std::string& file) {
    auto fail = [&](const std::string& what) { throw InputError(file, what); };
    SceneNode out;
    out.name = node.name.empty() ? "node " + std::to_string(index) : node.name;
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(out.name + ": 'matrix' needs 16 numbers");
        out.has_matrix = true;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out.matrix[c][r] = node.matrix[size_t(4 * c + r)];
    } else {
        if (!node.translation.empty() && node.translation.size() != 3) fail(out.name + ": 'translation' needs 3 numbers");
        if (!node.scale.empty() && node.scale.size() != 3) fail(out.name + ": 'scale' needs 3 numbers");
        if (!node.rotation.empty() && node.rotation.size() != 4) fail(out.name + ": 'rotation' needs 4 numbers");
        out.translation = vec3_or(node.translation, dvec3(0));
        out.scale = vec3_or(node.scale, dvec3(1));
        if (node.rotation.size() == 4)
            out.rotation = unit_rotation(node.rotation.data(), out.name + ": 'rotation'", fail);
    }
    const glm::dmat4 local = out.local();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(local[c][r])) fail(out.name + ": its transform is not finite");
    return out;
}

std::vector<glm::dmat4> gltf_instancing_rows(const tinygltf::Node& node, const AccessorReader& read, const std::string& name) {
    auto fail = [&](const std::string& what) { read.fail(what); };
    const auto it = node.extensions.find("EXT_mesh_gpu_instancing");
    if (it == node.extensions.end()) return {};
    if (!it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
        fail(name + ": EXT_mesh_gpu_instancing without attributes");
    const tinygltf::Value& attributes = it->second.Get("attributes");
    std::vector<double> t, r, sc;
    size_t rows = 0;
    auto take = [&](const char* key, int components, std::vector<double>& into) {
        if (!attributes.Has(key)) return;
        const tinygltf::Value& v = attributes.Get(key);
        if (!v.IsInt()) fail(name + ": EXT_mesh_gpu_instancing's " + key + " is not an accessor index");
        into = read.numbers(v.GetNumberAsInt(), components, name + " instancing " + key);
        const size_t n = into.size() / size_t(components);
        if (rows != 0 && n != rows) fail(name + ": EXT_mesh_gpu_instancing's attributes differ in count");
        rows = n;
    };
    take("TRANSLATION", 3, t);
    take("ROTATION", 4, r);
    take("SCALE", 3, sc);
    if (rows > kMaxInstances) fail(name + ": " + std::to_string(rows) + " instances (the limit is " + std::to_string(kMaxInstances) + ")");
    std::vector<glm::dmat4> out;
    for (size_t k = 0; k < rows; ++k) {
        SceneNode row;
        if (!t.empty()) row.translation = {t[3 * k], t[3 * k + 1], t[3 * k + 2]};
        if (!r.empty())
            row.rotation = unit_rotation(&r[4 * k], name + ": EXT_mesh_gpu_instancing's ROTATION row " + std::to_string(k), fail);
        if (!sc.empty()) row.scale = {sc[3 * k], sc[3 * k + 1], sc[3 * k + 2]};
        out.push_back(row.local());
    }
    return out;
}

}  // namespace fh
