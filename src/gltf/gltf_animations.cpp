#include "gltf/gltf_animations.h"

#include "gltf/gltf_deform.h"

namespace fh {

NodeAnimation read_gltf_animation(const tinygltf::Model& model, int index, const AccessorReader& read,
                                  const std::vector<int>& scene_node, const std::vector<SceneNode>& nodes) {
    auto fail = [&](const std::string& what) { read.fail(what); };
    const tinygltf::Animation& a = model.animations[size_t(index)];
    NodeAnimation anim;
    anim.name = a.name.empty() ? "animation " + std::to_string(index) : a.name;
    for (size_t k = 0; k < a.channels.size(); ++k) {
        const tinygltf::AnimationChannel& c = a.channels[k];
        const std::string what = anim.name + " channel " + std::to_string(k);
        NodeChannel channel;
        if (c.target_path == "translation") channel.property = NodeProperty::translation;
        else if (c.target_path == "rotation") channel.property = NodeProperty::rotation;
        else if (c.target_path == "scale") channel.property = NodeProperty::scale;
        else if (c.target_path == "weights") channel.property = NodeProperty::weights;
        else fail(what + ": target path '" + c.target_path + "' is not translation, rotation, scale or weights");
        if (c.target_node < 0 || size_t(c.target_node) >= model.nodes.size())
            fail(what + ": node " + std::to_string(c.target_node) + " does not exist");
        channel.node = scene_node[size_t(c.target_node)];
        if (channel.node < 0) continue;  // a node outside the scene shown
        if (nodes[size_t(channel.node)].has_matrix)
            fail(what + ": node " + std::to_string(c.target_node) + " has a 'matrix', which cannot be animated");
        if (c.sampler < 0 || size_t(c.sampler) >= a.samplers.size())
            fail(what + ": sampler " + std::to_string(c.sampler) + " does not exist");
        const tinygltf::AnimationSampler& sm = a.samplers[size_t(c.sampler)];
        Sampler& s = channel.sampler;
        s.rotation = channel.property == NodeProperty::rotation;
        s.components = s.rotation ? 4 : 3;
        if (channel.property == NodeProperty::weights) {
            const tinygltf::Node& target = model.nodes[size_t(c.target_node)];
            const size_t targets = target.mesh >= 0 && size_t(target.mesh) < model.meshes.size() ? morph_target_count(model, target.mesh, read) : 0;
            if (targets == 0) fail(what + ": weights of node " + std::to_string(c.target_node) + ", which has no morph targets");
            s.components = int(targets);
        }
        if (sm.interpolation == "STEP") s.interpolation = Interpolation3::step;
        else if (sm.interpolation == "CUBICSPLINE") s.interpolation = Interpolation3::cubic_spline;
        else if (sm.interpolation.empty() || sm.interpolation == "LINEAR") s.interpolation = Interpolation3::linear;
        else fail(what + ": interpolation '" + sm.interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
        s.times = read.numbers(sm.input, 1, what + " input");
        // Weights come as scalars, one per target a key.
        s.values = read.numbers(sm.output, channel.property == NodeProperty::weights ? 1 : s.components,
                                 what + " output");
        const size_t groups = s.interpolation == Interpolation3::cubic_spline ? 3 : 1;
        if (s.values.size() != groups * s.times.size() * size_t(s.components))
            fail(what + ": " + std::to_string(s.values.size() / size_t(s.components)) + " output values for " +
                 std::to_string(s.times.size()) + " keys");
        if (const std::string why = sampler_problem(s); !why.empty()) fail(what + ": " + why);
        anim.channels.push_back(std::move(channel));
    }
    return anim;
}

}  // namespace fh
