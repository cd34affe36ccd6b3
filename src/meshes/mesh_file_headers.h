// What a PLY header declares, and the first bytes of an STL file, checked
// against the file before Debian's assimp 5.2.5 reads it: it loops forever
// on a PLY header without end_header and allocates whatever a header
// declares (400 million vertices in a 200-byte file: 4.7 GB). Counts only;
// the data is assimp's (meshes/ply_lists.h walks it). OFF files are checked
// whole (meshes/off_lines.h).
#pragma once

#include <cstdint>
#include <string>

namespace fh {

struct PlyHeader {
    bool binary = false;
    // The vertex element has red, green and blue properties, each a uchar
    // (assimp reads n / 255) or a float or double (as it is). Colours of
    // other types assimp scales oddly (an int n as n / 255 + 0.5): not drawn.
    bool colors = false;
};

// InputError(path, ...) when the header is cut short or declares more data
// than the file holds.
PlyHeader check_ply_header(const std::string& path, std::uintmax_t file_size);
// InputError(path, ...) for an STL file assimp would read past the end of
// (assimp_replay::byte_order_mark).
void check_stl_start(const std::string& path, std::uintmax_t file_size);

}  // namespace fh
