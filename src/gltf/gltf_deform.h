// A glTF primitive's morph targets and a node's skin read into a
// Deformation (scene/deformation.h), every bound checked: targets as many
// vertices as the primitive, joints and inverse bind matrices one each,
// every vertex's joints inside the skin and its weights finite, >= 0 and
// not all zero (they are normalised to sum to 1, as the specification
// expects them to). Only the .cpp files of src/gltf include this header.
#pragma once

#include <string>
#include <vector>

#include "gltf/accessors.h"
#include "scene/deformation.h"

namespace fh {

// How many morph targets mesh m has: the same for each of its primitives,
// as the specification requires.
size_t morph_target_count(const tinygltf::Model& model, int m, const AccessorReader& read);

std::vector<MorphTarget> read_morph_targets(const tinygltf::Primitive& prim, const AccessorReader& read,
                                            size_t vertices, const std::string& what);

// The skin's inverse bind matrices, one per joint (identity when left out).
std::vector<glm::dmat4> read_inverse_binds(const tinygltf::Skin& skin, const AccessorReader& read,
                                           const std::string& what);

// Every JOINTS_n/WEIGHTS_n set of a primitive skinned by a skin of `joints` joints.
SkinWeights read_skin_weights(const tinygltf::Primitive& prim, const AccessorReader& read, size_t vertices,
                              size_t joints, const std::string& what);

}  // namespace fh
