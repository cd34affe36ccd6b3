// PNG output. A file is written under a temporary name in the same folder and
// renamed over the target, so a reader (or a killed run) only ever sees a
// whole file or none.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/image.h"

namespace fh {

std::vector<std::uint8_t> encode_png(const Image& image);

// Writes bytes to path atomically; throws std::runtime_error naming the path.
void write_file_atomic(const std::string& path, const std::vector<std::uint8_t>& bytes);

void write_png(const std::string& path, const Image& image);

// A PNG file that is whole: the signature, then chunks up to IEND at the end.
bool is_complete_png(const std::string& path);

}  // namespace fh
