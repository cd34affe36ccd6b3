#include "gltf/gltf_deform.h"

#include <cmath>

namespace fh {

namespace {

std::vector<dvec3> vectors(const std::vector<double>& v) {
    std::vector<dvec3> out(v.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

}  // namespace

size_t morph_target_count(const tinygltf::Model& model, int m, const AccessorReader& read) {
    const tinygltf::Mesh& mesh = model.meshes[size_t(m)];
    const size_t n = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    for (const tinygltf::Primitive& p : mesh.primitives)
        if (p.targets.size() != n) read.fail("mesh " + std::to_string(m) + ": its primitives have different numbers of morph targets");
    return n;
}

std::vector<MorphTarget> read_morph_targets(const tinygltf::Primitive& prim, const AccessorReader& read,
                                            size_t vertices, const std::string& what) {
    std::vector<MorphTarget> targets;
    for (size_t t = 0; t < prim.targets.size(); ++t) {
        const std::string named = what + " morph target " + std::to_string(t);
        MorphTarget target;
        for (const auto& [attribute, accessor] : prim.targets[t]) {
            // (TANGENT only where the primitive has tangents to move.)
            if (attribute != "POSITION" && attribute != "NORMAL" &&
                (attribute != "TANGENT" || !prim.attributes.count("TANGENT")))
                continue;
            std::vector<dvec3> v = vectors(read.numbers(accessor, 3, named + " " + attribute));
            if (v.size() != vertices)
                read.fail(named + ": " + attribute + " has " + std::to_string(v.size()) + " elements, POSITION " +
                          std::to_string(vertices));
            (attribute == "POSITION" ? target.positions : attribute == "NORMAL" ? target.normals : target.tangents) =
                std::move(v);
        }
        if (target.positions.empty()) target.positions.assign(vertices, dvec3(0));
        targets.push_back(std::move(target));
    }
    return targets;
}

std::vector<glm::dmat4> read_inverse_binds(const tinygltf::Skin& skin, const AccessorReader& read,
                                           const std::string& what) {
    const size_t joints = skin.joints.size();
    if (joints == 0) read.fail(what + ": its skin has no joints");
    if (skin.inverseBindMatrices < 0) return std::vector<glm::dmat4>(joints, glm::dmat4(1.0));  // the default
    const std::vector<double> m = read.numbers(skin.inverseBindMatrices, 16, what + " inverseBindMatrices");
    if (m.size() != 16 * joints)
        read.fail(what + ": " + std::to_string(m.size() / 16) + " inverse bind matrices for " + std::to_string(joints) +
                  " joints");
    std::vector<glm::dmat4> out;
    for (size_t j = 0; j < joints; ++j) {
        glm::dmat4 b;
        for (int k = 0; k < 16; ++k) b[k / 4][k % 4] = m[16 * j + size_t(k)];  // column-major, as glTF
        out.push_back(b);
    }
    return out;
}

SkinWeights read_skin_weights(const tinygltf::Primitive& prim, const AccessorReader& read, size_t vertices,
                              size_t skin_joints, const std::string& what) {
    SkinWeights s;
    // JOINTS_0/WEIGHTS_0, JOINTS_1/WEIGHTS_1, ...: four influences a set.
    std::vector<std::vector<double>> joints, weights;
    for (int set = 0;; ++set) {
        const auto j = prim.attributes.find("JOINTS_" + std::to_string(set));
        const auto w = prim.attributes.find("WEIGHTS_" + std::to_string(set));
        if (j == prim.attributes.end() && w == prim.attributes.end()) break;
        if (j == prim.attributes.end() || w == prim.attributes.end())
            read.fail(what + ": JOINTS_" + std::to_string(set) + " and WEIGHTS_" + std::to_string(set) +
                      " come together");
        joints.push_back(read.numbers(j->second, 4, what + " " + j->first));
        weights.push_back(read.numbers(w->second, 4, what + " " + w->first));
        if (joints.back().size() != 4 * vertices || weights.back().size() != 4 * vertices)
            read.fail(what + ": " + j->first + " and " + w->first + " need one element per vertex");
    }
    if (joints.empty()) read.fail(what + ": skinned, but it has no JOINTS_0 and WEIGHTS_0");
    const size_t k = 4 * joints.size();
    s.influences = int(k);
    s.joint.resize(vertices * k);
    s.weight.resize(vertices * k);
    for (size_t v = 0; v < vertices; ++v) {
        double sum = 0;
        for (size_t i = 0; i < k; ++i) {
            const double joint = joints[i / 4][4 * v + i % 4], weight = weights[i / 4][4 * v + i % 4];
            if (!(weight >= 0)) read.fail(what + ": vertex " + std::to_string(v) + " has a negative weight");
            if (weight > 0 && !(joint >= 0 && joint < double(skin_joints)))
                read.fail(what + ": vertex " + std::to_string(v) + " names joint " + std::to_string(std::int64_t(joint)) +
                          " of a skin of " + std::to_string(skin_joints));
            s.joint[v * k + i] = weight > 0 ? std::uint32_t(joint) : 0;
            s.weight[v * k + i] = weight;
            sum += weight;
        }
        if (!(sum > 0) || !std::isfinite(sum))
            read.fail(what + ": vertex " + std::to_string(v) + " has no joint weight");
        for (size_t i = 0; i < k; ++i) s.weight[v * k + i] /= sum;
    }
    return s;
}

}  // namespace fh
