// A glTF animation's channels: a sampler (anim/sampler.h) driving one
// property of one scene node (scene/node.h) -- its translation, rotation or
// scale. An animation is a set of channels on one clock: at time t each
// channel's sampler gives its node's property.
#pragma once

#include <string>
#include <vector>

#include "anim/sampler.h"

namespace fh {

struct Scene;

enum class NodeProperty { translation, rotation, scale, weights };

struct NodeChannel {
    int node = 0;  // into Scene::nodes
    NodeProperty property = NodeProperty::translation;
    Sampler sampler;
};

struct NodeAnimation {
    std::string name;  // the file's, or "animation N"
    std::vector<NodeChannel> channels;

    double start() const;  // the earliest key of its channels
    double end() const;    // the latest
};

// Each channel's value at time t (seconds) written into its node.
void apply_channels(const std::vector<NodeChannel>& channels, double t, Scene& scene);

}  // namespace fh
