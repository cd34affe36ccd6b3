#include "yaml/node_paths.h"

#include <algorithm>
#include <cmath>

#include "yaml/key_list.h"

namespace fh {

namespace {

// The node called `name`: exactly one must be.
int find_node(const YamlReader& r, const YAML::Node& at, const Scene& scene, const std::string& name) {
    int found = -1, count = 0;
    std::vector<std::string> names;
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        names.push_back(scene.nodes[i].name);
        if (scene.nodes[i].name == name) found = int(i), ++count;
    }
    if (count > 1)
        r.fail(at, std::to_string(count) + " nodes are named '" + name +
                       "' (glTF names need not be unique): rename one in the file to animate it");
    if (found < 0) {
        if (scene.nodes.empty()) r.fail(at, "no node named '" + name + "': the scene has no glTF nodes");
        const std::string hint = closest_match(name, names);
        r.fail(at, "no node named '" + name + "' in the scene's glTF files" +
                       (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    if (scene.nodes[size_t(found)].has_matrix)
        r.fail(at, "node '" + name + "' is placed by a matrix, which glTF never animates: only TRS nodes move");
    return found;
}

// One value: translation 3 numbers, scale 1 or 3 non-zero, rotation 4 made unit.
void read_node_value(const YamlReader& r, const YAML::Node& node, NodeProperty property, const std::string& path,
                     std::vector<double>& out) {
    if (property == NodeProperty::translation) {
        const dvec3 v = r.vec3(node, path);
        out.insert(out.end(), {v.x, v.y, v.z});
    } else if (property == NodeProperty::scale) {
        const dvec3 v = node.IsSequence() ? r.vec3(node, path) : dvec3(r.number(node, path));
        if (v.x == 0 || v.y == 0 || v.z == 0) r.fail(node, "'" + path + "' must not be 0 on any axis");
        out.insert(out.end(), {v.x, v.y, v.z});
    } else {
        if (!node.IsSequence() || node.size() != 4)
            r.fail(node, "'" + path + "' must be a quaternion [x, y, z, w], " + got(node));
        double q[4], length = 0;
        for (size_t i = 0; i < 4; ++i) {
            q[i] = r.number(node[i], path);
            length += q[i] * q[i];
        }
        length = std::sqrt(length);
        if (!(length > 1e-12) || !std::isfinite(length)) r.fail(node, "'" + path + "' must not be the zero quaternion");
        for (const double c : q) out.push_back(c / length);
    }
}

}  // namespace

bool is_node_path(const std::string& key) { return key.rfind("nodes.", 0) == 0; }

NodeChannel read_node_path(const YamlReader& r, const MapReader::Entry& entry, const Movie& movie) {
    const std::string& path = entry.key;
    // Node names may hold dots (Blender's "Cylinder.001"): the property is the last word.
    const size_t dot = path.rfind('.');
    const std::string name = dot > 6 ? path.substr(6, dot - 6) : "";
    const std::string property = dot > 6 ? path.substr(dot + 1) : "";
    const std::vector<std::string> properties = {"translation", "rotation", "scale"};
    if (name.empty() || property.empty())
        r.fail(entry.key_node, "a node's path is nodes.NAME.translation, nodes.NAME.rotation or nodes.NAME.scale");
    NodeChannel c;
    c.node = find_node(r, entry.key_node, movie.scene, name);
    const auto it = std::find(properties.begin(), properties.end(), property);
    if (it == properties.end()) {
        const std::string hint = closest_match(property, properties);
        r.fail(entry.key_node, "unknown property '" + property + "' in '" + path +
                                   "': a node can animate translation, rotation, scale" +
                                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    c.property = NodeProperty(it - properties.begin());
    Sampler& s = c.sampler;
    s.components = c.property == NodeProperty::rotation ? 4 : 3;
    s.rotation = c.property == NodeProperty::rotation;
    if (entry.value.IsNull()) r.fail(entry.key_node, "missing value for '" + path + "'");
    if (!entry.value.IsMap()) {
        s.times = {0};
        read_node_value(r, entry.value, c.property, path, s.values);
        return c;
    }
    const MapReader m(r, entry.value, "'" + path + "'", {"value", "keyframes", "interpolation"});
    if (m.has("value") == m.has("keyframes")) r.fail(m.node(), "'" + path + "' needs one of 'value' or 'keyframes'");
    if (m.has("value")) {
        if (m.has("interpolation")) r.fail(m.find("interpolation")->key_node, "'interpolation' only applies to 'keyframes'");
        s.times = {0};
        read_node_value(r, m.value("value"), c.property, path, s.values);
        return c;
    }
    for (const KeyNode& key : read_key_list(r, m.value("keyframes"), movie)) {
        s.times.push_back(key.frame / movie.fps);
        read_node_value(r, key.value, c.property, path, s.values);
    }
    // glTF's own two (CUBICSPLINE needs tangents a YAML key does not have).
    if (m.has("interpolation"))
        s.interpolation = Interpolation3(r.choice(m.value("interpolation"), "node interpolation", {"step", "linear"}));
    return c;
}

}  // namespace fh
