// The list lengths in a PLY file's data, checked as Debian's assimp 5.2.5
// will read them, before it does. Its reader sizes a list by the length it
// reads, then reads the values: one length of 4 billion in a 200-byte file is
// a 34 GB allocation, and 1.5 billion took 30 s and 11.7 GB (fuzzing found
// it). A truncated binary file is as bad: past the file's end assimp reads
// the line-end bytes its buffer was filled with, 0x0a0a0a0a values long.
//
// So the file is read here the way assimp reads it -- its line buffer and
// where each value ends (replayed in meshes/assimp_replay.h), its header
// parser with its quirks (an element of a name it does not know gets its
// count from that name: usually 0) -- and a list longer than what follows
// it on its line (ASCII) or in the file (binary) is refused. Where assimp
// itself would give up on a value (it throws), the check stops: assimp
// reads no further. The header's elements are checked too: a second vertex
// or face element makes assimp write past its arrays, a face element of
// texture coordinates without indices read through a null pointer -- and
// so are a face's 6 to 8 texture coordinates over fewer than 3 or 4 vertex
// indices, which assimp reads past (one index for each two coordinates), a
// line of 1 MiB - 1 bytes, past which it reads its 1 MiB line buffer, and
// data that ends before its elements do (assimp reads the last line again
// for each instance left: n^2 values from a list of n).
#pragma once

#include <string>

namespace fh {

// InputError(path, line, ...) for a list longer than its data, a binary
// file cut short, or a line that would make assimp read the bytes left in
// its buffer from an earlier line.
void check_ply_lists(const std::string& path);

}  // namespace fh
