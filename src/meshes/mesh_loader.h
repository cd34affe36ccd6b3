// Triangle meshes from files: OBJ, PLY (ASCII and binary), STL (ASCII and
// binary) and OFF, read by assimp and handed over as one indexed triangle list.
// Loading is strict: anything assimp cannot read, or reads only by guessing
// (an index it clamps, a value it replaces by 0, a file that ends early), is an
// fh::InputError naming the file; nothing is printed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.h"

namespace fh {

// A mesh as read: vertices joined (a position shared by several triangles is
// stored once), triangles of non-zero area.
struct MeshData {
    // Exactly the file's values as assimp reads them: Debian's assimp reads
    // coordinates as 32-bit floats, so 0.1 comes out as 0.1f (0.100000001...),
    // also from a PLY `double` property.
    std::vector<dvec3> positions;
    // One per position, as the file gives them (not normalised), or empty
    // when the file gives none for some vertex a triangle uses (an OBJ group
    // or face without them, a zero normal), or only STL's per-facet normals,
    // which are not vertex normals. A NaN or infinite normal is an error.
    std::vector<dvec3> normals;
    // One per position when every vertex has a colour (a PLY's red, green
    // and blue, an OBJ's `v x y z r g b`), each channel in [0, 1]; else empty.
    std::vector<dvec3> colors;
    // Indices into positions, in the file's winding order.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // Triangles of zero area dropped: two corners the same vertex, or
    // (v1 - v0) x (v2 - v0) exactly zero.
    std::size_t degenerate_dropped = 0;
};

// The most triangles a mesh may have: what a few GB hold while it is read.
// Reading is the peak: assimp holds the file and its faces and vertices
// before joining, besides what we build -- measured at 750,000 triangles,
// ~360 B per triangle for binary PLY, ~560 B for OBJ and binary STL -- so a
// mesh at the limit reads in 1.8-2.8 GB. Loaded, the tracer needs ~100 B per
// triangle (vertices, flat copy, BVH): 0.5 GB.
inline constexpr std::size_t kMaxMeshTriangles = 5'000'000;

// Reads the mesh file at `path`; its format is its extension, in any case:
// .obj, .ply, .stl, .off. Polygons are triangulated (ear clipping; assimp's),
// points and lines are left out, all of the file's objects, groups and solids
// make one mesh. Missing file, unknown extension, unreadable or inconsistent
// data (an index out of range, NaN or infinite coordinates, a file cut short),
// no triangles, more than `max_triangles` of them: InputError.
MeshData load_mesh(const std::string& path, std::size_t max_triangles = kMaxMeshTriangles);

}  // namespace fh
