// The files a run reads -- scene and movie files, placements tables, meshes,
// glTF files and what their uris name -- checked alike before they are read,
// and remembered, so that nothing the run writes (an image, a table, a mesh,
// raw video) can replace one of them: `firsthit frames model.gltf
// --raw-video model.bin` once truncated the model it had just read.
#pragma once

#include <string>

namespace fh {

// Why `path` cannot be read as an input file, in one wording for every
// loader: "no such file", "is a folder", "not a regular file" (a device or a
// pipe, which may never end) or the system's reason; "" when it can.
std::string why_unreadable(const std::string& path);

// Remembers the file at `path` (when there is one) as read by this run.
void note_input_file(const std::string& path);

// InputError naming `path` when it is a file this run has read, by any name
// (a link to it, or another spelling of its path).
void check_not_an_input(const std::string& path);

}  // namespace fh
