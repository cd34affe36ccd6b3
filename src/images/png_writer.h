// PNG output: an Image encoded as PNG, and written as a file that is whole
// or absent (write_file_atomic, files/atomic_file.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/image.h"

namespace fh {

std::vector<std::uint8_t> encode_png(const Image& image);

// The CRC-32 of PNG's chunks (ISO 3309), as encode_png computes it: zlib's
// crc32(), through stb_image_write's STBIW_CRC32 hook.
std::uint32_t png_crc32(const unsigned char* data, size_t len);

// encode_png, then write_file_atomic.
void write_png(const std::string& path, const Image& image);

// A PNG file that is whole: the signature, then chunks up to IEND at the end.
bool is_complete_png(const std::string& path);

// A PNG file's width and height, from its header; nullopt if it is no PNG.
std::optional<std::pair<int, int>> png_size(const std::string& path);

}  // namespace fh
