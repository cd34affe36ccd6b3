// Where in a text mesh file a bad vertex or face is. assimp gives a line for
// its own parse errors only; the problems found in what it read (a NaN
// coordinate, an index it clamped) name a vertex or a face, or nothing. On
// such an error the file is scanned again, record by record as the format
// lays them out, for the line and column to print. Only on the error path:
// loading a good file never reads it twice.
#pragma once

#include <array>
#include <string>

namespace fh {

enum class MeshFormat { obj, ply, stl, off };

struct TextPosition {
    int line = 0;    // 1-based; 0: not found, or not a text file
    int column = 0;  // 1-based, of the offending number
};

// What of a vertex is searched for a non-finite number: its coordinates
// (a record's first three numbers), its normal (OBJ: in `vn` records;
// others: any number of the vertex's record) or its colour (any number of
// the vertex's record: its coordinates, checked before, are finite).
enum class VertexPart { coordinates, normal, colour };

// The first number that is NaN or infinite as a float (as assimp reads it:
// 1e39 is infinite) in the file's vertex records -- OBJ `v`, ASCII STL
// `vertex`, OFF and ASCII PLY vertex lines -- in `part` of a record.
// index >= 0: only in the index-th record (from 0, in file order); index <
// 0 and `position` given: in the first record whose coordinates are those
// (NaN matching NaN) and hold one; else in the first record that holds one.
TextPosition nonfinite_vertex_position(const std::string& path, MeshFormat format, VertexPart part,
                                       long long index = -1, const std::array<float, 3>* position = nullptr);

// The first vertex index in the file's face records (OBJ `f`, OFF and ASCII
// PLY face lines) that names no vertex: negative or past the last (OBJ:
// 0, past the last, or a relative index before the first).
TextPosition bad_face_index_position(const std::string& path, MeshFormat format);

}  // namespace fh
