#include "images/png_writer.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>

#include <zlib.h>

#include "files/atomic_file.h"
#include "images/deflate.h"

// stb_image_write lays out the PNG (the Sub filter on every row, chunks, CRCs)
// and is compiled here, once for the program (images/image_writer.cpp calls its
// JPEG, BMP and TGA writers); the deflate inside is ours,
// zlib_compress_runs, through stb's hook for it: after the Sub filter a
// frame is mostly runs of 0, which it codes ~4x faster than zlib at level 1
// (docs/speed.md). The chunks' CRCs are zlib's crc32() (fh::png_crc32, below).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#define STBIW_ZLIB_COMPRESS fh_png_deflate
static unsigned char* fh_png_deflate(unsigned char* data, int data_len, int* out_len, int quality);
#define STBIW_CRC32(buffer, len) fh::png_crc32(buffer, size_t(len))
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

// stb frees the result with free(), so it is allocated with malloc(). No
// exception may cross stb's C code (it would leak stb's buffers): running out
// of memory is a null result, which stb reports as a failure.
static unsigned char* fh_png_deflate(unsigned char* data, int data_len, int* out_len, int) {
    thread_local std::vector<std::uint8_t> stream;  // reused: no fresh pages per frame
    stream.clear();
    try {
        fh::zlib_compress_runs(std::span<const std::uint8_t>(data, size_t(data_len)), stream);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
    auto* out = static_cast<unsigned char*>(std::malloc(stream.size()));
    if (!out) return nullptr;
    std::memcpy(out, stream.data(), stream.size());
    *out_len = int(stream.size());
    return out;
}

// Every row with the Sub filter (each byte minus the one a pixel to its
// left): the tracer's smooth shading becomes runs of 0, as small as stb's
// choice per row and twice as fast to make. Set once, before any thread starts.
static const bool kPngFilterChosen = (stbi_write_force_png_filter = 1, true);

namespace fh {

// zlib's crc32() rather than a CRC-32 of our own: it is faster (~2.8x our
// former slicing-by-8 one, docs/speed.md) and zlib is linked already. stb
// passes a chunk's length as an int, which always fits crc32()'s 32-bit uInt
// (the largest frame, 16384x16384, is ~805 MB of filtered bytes); crc32_z,
// the same CRC with a z_size_t length, keeps any size_t whole all the same.
std::uint32_t png_crc32(const unsigned char* data, size_t len) {
    return std::uint32_t(crc32_z(0L, data, z_size_t(len)));
}

std::vector<std::uint8_t> encode_png(const Image& image) {
    std::vector<std::uint8_t> out;
    auto append = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<std::uint8_t>*>(ctx);
        const auto* p = static_cast<const std::uint8_t*>(data);
        v->insert(v->end(), p, p + size);
    };
    if (!stbi_write_png_to_func(append, &out, image.width, image.height, 3, image.rgb.data(),
                                image.width * 3))
        throw std::runtime_error("PNG encoding failed: out of memory for a " + std::to_string(image.width) +
                                 "x" + std::to_string(image.height) + " image");
    return out;
}

void write_png(const std::string& path, const Image& image) {
    write_file_atomic(path, encode_png(image));
}

bool is_complete_png(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return false;
    const std::streamoff size = in.tellg();
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    // The IEND chunk: zero length, type, CRC.
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (size < std::streamoff(sizeof signature + sizeof iend)) return false;
    unsigned char head[8], tail[12];
    in.seekg(0);
    in.read(reinterpret_cast<char*>(head), sizeof head);
    in.seekg(size - std::streamoff(sizeof tail));
    in.read(reinterpret_cast<char*>(tail), sizeof tail);
    return in && std::memcmp(head, signature, sizeof head) == 0 &&
           std::memcmp(tail, iend, sizeof tail) == 0;
}

std::optional<std::pair<int, int>> png_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[24];  // signature, IHDR's length and type, width, height
    if (!in.read(reinterpret_cast<char*>(head), sizeof head) || std::memcmp(head + 1, "PNG", 3) != 0 ||
        std::memcmp(head + 12, "IHDR", 4) != 0)
        return std::nullopt;
    auto big_endian = [&](int at) {
        return int((std::uint32_t(head[at]) << 24 | std::uint32_t(head[at + 1]) << 16 |
                    std::uint32_t(head[at + 2]) << 8 | head[at + 3]) & 0x7fffffff);
    };
    return std::pair(big_endian(16), big_endian(20));
}

}  // namespace fh
