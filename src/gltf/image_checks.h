// PNG and JPEG bytes checked before Debian's stb_image 2.27 decodes them
// (gltf_model.cpp's decode_image): what it reads past its tables or out of
// uninitialised memory, or inflates without bound, refused with the reason.
//   - a JPEG Huffman table of more than 256 codes: stb_image writes them past
//     the table, over the next table's lengths, and then reads wherever those
//     say (a crash; CVE-2022-28042, fixed in 2.28);
//   - a JPEG scan that decodes with a Huffman table not yet defined: stb_image
//     reads one it never initialised (fixed in 2.28);
//   - PNG image data that is not valid zlib (zlib's own inflate says): stb
//     2.27 takes distance codes 30 and 31 for a distance of 0 and fills the
//     image with whatever its heap held before (fixed in 2.28), and inflates
//     more data than the image needs without limit (a compression bomb).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fh {

// The unsigned 32-bit number PNG's chunks store at p, most significant byte first.
inline std::uint32_t big_endian_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// Empty when stb_image may decode these bytes, else why not. Only what the
// checks above look for: anything else wrong is left to stb_image to refuse.
std::string png_problem(const unsigned char* bytes, std::size_t size);
std::string jpeg_problem(const unsigned char* bytes, std::size_t size);

}  // namespace fh
