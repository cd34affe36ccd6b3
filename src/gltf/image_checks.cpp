#include "gltf/image_checks.h"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace fh {

namespace {

// The bytes a PNG's filtered rows take: one filter byte a row, each of the
// seven Adam7 passes its own rows when interlaced. 0 for a header stb
// refuses itself.
std::uint64_t png_raw_bytes(std::uint64_t w, std::uint64_t h, int depth, int color, int interlace) {
    const int channels = color == 0 ? 1 : color == 2 ? 3 : color == 3 ? 1 : color == 4 ? 2 : color == 6 ? 4 : 0;
    if (channels == 0 || (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16)) return 0;
    const std::uint64_t bits = std::uint64_t(depth) * std::uint64_t(channels);
    auto rows = [&](std::uint64_t pw, std::uint64_t ph) { return pw && ph ? ph * (1 + (pw * bits + 7) / 8) : 0; };
    if (interlace == 0) return rows(w, h);
    static const int pass[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                   {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
    std::uint64_t total = 0;
    for (const auto& p : pass) {
        const std::uint64_t pw = w > std::uint64_t(p[0]) ? (w - p[0] + p[2] - 1) / p[2] : 0;
        const std::uint64_t ph = h > std::uint64_t(p[1]) ? (h - p[1] + p[3] - 1) / p[3] : 0;
        total += rows(pw, ph);
    }
    return total;
}

}  // namespace

std::string png_problem(const unsigned char* bytes, std::size_t size) {
    std::uint64_t expected = 0;
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return "";
    std::vector<unsigned char> out(std::size_t(1) << 16);
    std::uint64_t produced = 0;
    bool ended = false;
    std::string why;
    // The chunks, from after the signature, until one is cut short.
    for (std::size_t at = 8; why.empty() && !ended && at + 12 <= size;) {
        const std::uint32_t length = big_endian_u32(bytes + at);
        if (length > size - at - 12) break;
        const unsigned char* type = bytes + at + 4;
        const unsigned char* data = bytes + at + 8;
        if (std::memcmp(type, "IHDR", 4) == 0 && length >= 13)
            expected = png_raw_bytes(big_endian_u32(data), big_endian_u32(data + 4), data[8], data[9], data[12]);
        if (std::memcmp(type, "IEND", 4) == 0) break;
        if (std::memcmp(type, "IDAT", 4) == 0) {
            if (expected == 0) break;  // no header stb reads: its to refuse
            z.next_in = const_cast<unsigned char*>(data);
            z.avail_in = length;
            while (why.empty() && !ended && z.avail_in > 0) {
                z.next_out = out.data();
                z.avail_out = unsigned(out.size());
                const int r = inflate(&z, Z_NO_FLUSH);
                produced += out.size() - z.avail_out;
                // stb_image keeps what follows the rows unused; a mebibyte
                // more is harmless, gigabytes are not.
                if (produced > expected + (std::uint64_t(1) << 20))
                    why = "its image data inflates to more than the " + std::to_string(expected) +
                          " bytes its size needs (a compression bomb?)";
                else if (r == Z_STREAM_END)
                    ended = true;
                else if (r == Z_DATA_ERROR && !(z.msg && std::strcmp(z.msg, "incorrect data check") == 0))
                    why = std::string("its image data is not valid zlib (") + (z.msg ? z.msg : "a data error") +
                          "), which stb_image 2.27 would decode from uninitialised memory";
                else if (r != Z_OK)
                    break;  // wants more input (the next IDAT), or ends its check (stb ignores it)
            }
        }
        at += 12 + std::size_t(length);
    }
    inflateEnd(&z);
    return why;
}

std::string jpeg_problem(const unsigned char* bytes, std::size_t size) {
    bool defined[2][4] = {};  // [DC, AC][table]
    bool progressive = false;
    std::size_t at = 2;  // after the SOI marker
    while (at + 1 < size) {
        if (bytes[at] != 0xff) return "";  // not a marker: stb_image's to refuse
        while (at < size && bytes[at] == 0xff) ++at;
        if (at >= size) return "";
        const unsigned char marker = bytes[at++];
        if (marker == 0xd9) return "";                                   // EOI
        if ((marker >= 0xd0 && marker <= 0xd7) || marker == 0x01) continue;  // no length
        if (at + 2 > size) return "";
        const std::size_t length = std::size_t(bytes[at]) << 8 | bytes[at + 1];
        if (length < 2 || length > size - at) return "";
        const unsigned char* s = bytes + at + 2;
        const std::size_t n = length - 2;
        if (marker == 0xc2) progressive = true;
        if (marker == 0xc4)  // DHT: tables of a class and number, 16 counts, then the codes
            for (std::size_t p = 0; p + 17 <= n;) {
                std::size_t codes = 0;
                for (int k = 1; k <= 16; ++k) codes += s[p + k];
                if (codes > 256)
                    return "a JPEG Huffman table of " + std::to_string(codes) +
                           " codes (at most 256; stb_image 2.27 would write past its table)";
                if ((s[p] >> 4) <= 1 && (s[p] & 15) <= 3) defined[s[p] >> 4][s[p] & 15] = true;
                p += 17 + codes;
            }
        at += length;
        if (marker != 0xda) continue;
        // SOS: each component's DC and AC tables, then the spectral range.
        const std::size_t components = n >= 1 ? s[0] : 0;
        if (n < 1 + 2 * components + 3) return "";
        const unsigned start = s[1 + 2 * components], end = s[2 + 2 * components];
        const unsigned high = s[3 + 2 * components] >> 4;
        // A baseline scan decodes both; a progressive one its DC table in
        // a first DC scan, its AC table in an AC scan.
        const bool uses_dc = !progressive || (start == 0 && high == 0);
        const bool uses_ac = !progressive || end > 0;
        for (std::size_t c = 0; c < components; ++c) {
            const unsigned dc = s[2 + 2 * c] >> 4, ac = s[2 + 2 * c] & 15;
            if (dc > 3 || ac > 3) return "";
            if ((uses_dc && !defined[0][dc]) || (uses_ac && !defined[1][ac]))
                return "a JPEG scan decodes with a Huffman table defined nowhere before it (stb_image 2.27 "
                       "would read one it never set)";
        }
        // The entropy-coded data, up to the next marker (0xff, then neither
        // a stuffed 0 nor a restart marker).
        while (at + 1 < size &&
               !(bytes[at] == 0xff && bytes[at + 1] != 0 && !(bytes[at + 1] >= 0xd0 && bytes[at + 1] <= 0xd7)))
            ++at;
    }
    return "";
}

}  // namespace fh
