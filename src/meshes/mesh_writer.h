// World-space triangles written as a mesh file any viewer opens (firsthit
// export): PLY (binary, little-endian, double coordinates) or OBJ (text,
// 17 significant digits), by the file's extension; each triangle with its
// own three vertices. Written whole or not at all (files/atomic_file.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/vec.h"

namespace fh {

using WorldTriangle = std::array<dvec3, 3>;

// UsageError when the extension is neither .ply nor .obj (any case).
void check_mesh_output(const std::string& path);

void write_mesh(const std::string& path, const std::vector<WorldTriangle>& triangles);

}  // namespace fh
