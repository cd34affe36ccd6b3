// The counts a PLY or OFF header declares, checked against the file before
// assimp reads it: Debian's assimp 5.2.5 loops forever on a PLY header
// without end_header and allocates whatever a header declares (400 million
// vertices in a 200-byte file: 4.7 GB). Counts only; the data is assimp's.
#pragma once

#include <cstdint>
#include <string>

namespace fh {

// InputError(path, ...) when the header is cut short or declares more data
// than the file holds. Returns true for binary PLY data.
bool check_ply_header(const std::string& path, std::uintmax_t file_size);
void check_off_header(const std::string& path, std::uintmax_t file_size);

}  // namespace fh
