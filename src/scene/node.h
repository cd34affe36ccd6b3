// The nodes of a glTF file placed in a scene: a hierarchy of transforms,
// each node's translation, rotation (a unit quaternion) and scale, or one
// matrix, in its parent's space. Meshes (as instances), cameras and lights
// hang on nodes; when a node moves -- its file's animation, a movie's
// `nodes.NAME.*` path, the group the file is placed in -- place_nodes
// carries everything on it to where it now is.
#pragma once

#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "core/vec.h"

namespace fh {

struct Scene;

struct SceneNode {
    std::string name;   // the file's, or "node N" for an unnamed one
    int parent = -1;    // a node before this one, or -1: a top node of its file
    int group = -1;     // a top node: the scene group its file is placed in (-1: the world)
    dvec3 translation{0};
    glm::dquat rotation{1, 0, 0, 0};  // w, x, y, z: unit
    dvec3 scale{1};
    bool has_matrix = false;  // `matrix` instead of TRS (never animated)
    std::vector<double> weights;  // its mesh's morph target weights (scene/deformation.h)
    glm::dmat4 matrix{1.0};

    glm::dmat4 local() const;
};

// Each node's matrix to the world, parents first (nodes are stored so):
// its group's, its parents', its own.
std::vector<glm::dmat4> node_matrices(const Scene& scene);

// Everything on a node placed from the nodes as they stand: instances,
// cameras (eye at the node's origin, looking down its -z, up its +y) and
// lights (at its origin, shining down its -z).
void place_nodes(Scene& scene);

}  // namespace fh
