// World-space triangles written as a mesh file any viewer opens (firsthit
// export): PLY (binary, little-endian, double coordinates) or OBJ (text,
// 17 significant digits), by the file's extension; each triangle with its
// own three vertices, and, when given, each vertex's colour (linear, in
// [0, 1]: PLY uchar red green blue, round(255 c); OBJ's `v x y z r g b`).
// Written whole or not at all (files/atomic_file.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/vec.h"

namespace fh {

using WorldTriangle = std::array<dvec3, 3>;

// UsageError when the extension is neither .ply nor .obj (any case).
void check_mesh_output(const std::string& path);

// colors: empty, or one per triangle (its three vertices' colours).
void write_mesh(const std::string& path, const std::vector<WorldTriangle>& triangles,
                const std::vector<WorldTriangle>& colors = {});

}  // namespace fh
