#include "anim/node_channel.h"

#include <algorithm>

#include "scene/scene.h"

namespace fh {

double NodeAnimation::start() const {
    double t = 0;
    for (size_t k = 0; k < channels.size(); ++k)
        t = k == 0 ? channels[k].sampler.start() : std::min(t, channels[k].sampler.start());
    return t;
}

double NodeAnimation::end() const {
    double t = 0;
    for (const NodeChannel& c : channels) t = std::max(t, c.sampler.end());
    return t;
}

void apply_channels(const std::vector<NodeChannel>& channels, double t, Scene& scene) {
    for (const NodeChannel& c : channels) {
        const std::vector<double> v = sample(c.sampler, t);
        SceneNode& n = scene.nodes[size_t(c.node)];
        switch (c.property) {
        case NodeProperty::translation: n.translation = {v[0], v[1], v[2]}; break;
        case NodeProperty::scale: n.scale = {v[0], v[1], v[2]}; break;
        case NodeProperty::rotation: n.rotation = glm::dquat(v[3], v[0], v[1], v[2]); break;  // w, x, y, z
        case NodeProperty::weights: n.weights = v; break;
        }
    }
}

}  // namespace fh
