// CRC-32 (ISO 3309, as PNG's chunks and gzip use it), eight bytes a step
// ("slicing by 8"): stb_image_write's own goes a byte at a time, and took a
// seventh of a frame's PNG time doing it (README, Speed).
#pragma once

#include <cstdint>
#include <span>

namespace fh {

std::uint32_t crc32(std::span<const std::uint8_t> data);

}  // namespace fh
