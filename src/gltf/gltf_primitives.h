// A glTF mesh primitive as a firsthit mesh: TRIANGLES, strips and fans
// numbered as the specification numbers them, indexed or not, with their
// normals, the texture coordinates their base colour texture reads (moved
// by KHR_texture_transform) and their vertex colours (COLOR_0). Problems
// are InputError naming the file.
#pragma once

#include <string>

#include "scene/mesh.h"
#include "gltf/accessors.h"

namespace fh {

// What the specification asks of every primitive, drawn or not: its
// attributes' accessors as many as POSITION's, a vertex count its mode can
// use (a multiple of 3 for triangles, of 2 for lines), and every texture
// coordinate set its material reads. what: names it in messages.
void check_gltf_primitive(const tinygltf::Model& model, const AccessorReader& read, const tinygltf::Primitive& prim,
                          const std::string& what);

// A primitive of triangles, strips or fans (checked) as a mesh.
Mesh read_gltf_primitive(const tinygltf::Model& model, const AccessorReader& read, const tinygltf::Primitive& prim,
                         const std::string& what);

}  // namespace fh
