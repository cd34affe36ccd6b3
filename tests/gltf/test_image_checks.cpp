// The PNG and JPEG checks before stb_image 2.27 decodes (gltf/image_checks.h):
// each input stb would read past its tables, read from memory it never set,
// or inflate without bound is refused with its reason; valid images pass.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

#include "gltf/image_checks.h"

namespace fh {
namespace {

std::string be32_bytes(std::uint32_t v) {
    return {char(v >> 24), char(v >> 16 & 0xff), char(v >> 8 & 0xff), char(v & 0xff)};
}

std::string chunk(const std::string& type, const std::string& data) {
    return be32_bytes(std::uint32_t(data.size())) + type + data + be32_bytes(0);  // stb checks no CRC
}

// A PNG of `w` x `h` RGBA texels (8 bits, interlaced or not) whose image data is `idat`.
std::string png_with(std::uint32_t w, std::uint32_t h, const std::string& idat, bool interlaced = false) {
    const std::string header = be32_bytes(w) + be32_bytes(h) + std::string("\x08\x06\x00\x00", 4) + char(interlaced);
    return "\x89PNG\r\n\x1a\n" + chunk("IHDR", header) + chunk("IDAT", idat) + chunk("IEND", "");
}

std::string compressed(const std::string& raw) {
    uLongf n = compressBound(uLong(raw.size()));
    std::string out(n, '\0');
    compress(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
    out.resize(n);
    return out;
}

std::string png_check(const std::string& png) {
    return png_problem(reinterpret_cast<const unsigned char*>(png.data()), png.size());
}
std::string jpeg_check(const std::string& jpeg) {
    return jpeg_problem(reinterpret_cast<const unsigned char*>(jpeg.data()), jpeg.size());
}

// A deflate stream's bits: fields from their lowest bit, Huffman codes from their highest.
struct Bits {
    std::string bytes;
    int used = 8;
    void put(unsigned value, int n) {
        for (int i = 0; i < n; ++i) {
            if (used == 8) bytes += '\0', used = 0;
            bytes.back() = char(bytes.back() | ((value >> i & 1) << used++));
        }
    }
    void code(unsigned value, int n) {
        for (int i = n - 1; i >= 0; --i) put(value >> i & 1, 1);
    }
};

TEST(ImageChecks, ValidPngsPass) {
    // 2 x 2 texels: two rows of a filter byte and 8 bytes.
    EXPECT_EQ(png_check(png_with(2, 2, compressed(std::string(18, '\x7f')))), "");
    // Interlaced, 3 x 3: passes 1, 4, 5, 6 and 7 hold rows of 1, 1, 2, 1
    // and 3 texels, a filter byte each: 5 + 5 + 9 + 2 x 5 + 13 = 42 bytes.
    EXPECT_EQ(png_check(png_with(3, 3, compressed(std::string(42, '\0')), true)), "");
    // The image data split over several IDAT chunks.
    const std::string idat = compressed(std::string(18, '\x7f'));
    std::string split = png_with(2, 2, idat.substr(0, 5));
    split.insert(split.find("IEND") - 4, chunk("IDAT", idat.substr(5)));
    EXPECT_EQ(png_check(split), "");
}

TEST(ImageChecks, PngDataThatIsNotZlibIsRefused) {
    // A fixed-Huffman block: the filter byte as a literal, then a copy of
    // length 3 at distance code 30 -- no distance in deflate; stb 2.27 took
    // it for 0 and copied texels from memory it never set.
    Bits b;
    b.bytes = "\x78\x01";
    b.put(1, 1);        // the last block
    b.put(1, 2);        // fixed Huffman codes
    b.code(0x30, 8);    // literal 0
    b.code(1, 7);       // length 3 (code 257)
    b.code(30, 5);      // distance code 30
    b.code(0, 7);       // end of block
    EXPECT_EQ(png_check(png_with(1, 1, b.bytes)),
              "its image data is not valid zlib (invalid distance code), which stb_image 2.27 would decode from "
              "uninitialised memory");
}

TEST(ImageChecks, PngDataFarBeyondItsSizeIsRefused) {
    // 1 x 1 texel needs 5 bytes; 3 MiB of zeros compress to 3 KB.
    EXPECT_EQ(png_check(png_with(1, 1, compressed(std::string(3 << 20, '\0')))),
              "its image data inflates to more than the 5 bytes its size needs (a compression bomb?)");
    EXPECT_EQ(png_check(png_with(1, 1, compressed(std::string(1 << 20, '\0')))), "");  // a mebibyte more is let be
}

// A JPEG's segment: its marker, then its length (its own two bytes counted).
std::string segment(unsigned char marker, const std::string& data) {
    const std::size_t n = data.size() + 2;
    return std::string("\xff", 1) + char(marker) + char(n >> 8) + char(n & 0xff) + data;
}

// A Huffman table of class (0 DC, 1 AC) and number, with `codes` codes of 8 bits.
std::string huffman_table(int table_class, int number, int codes) {
    std::string counts(16, '\0');
    std::string symbols;
    for (int left = codes, k = 7; left > 0; ++k) {
        const int n = left > 255 ? 255 : left;
        counts[std::size_t(k)] = char(n);
        left -= n;
    }
    for (int i = 0; i < codes; ++i) symbols += char(i & 0xff);
    return char(table_class << 4 | number) + counts + symbols;
}

const std::string kSoi("\xff\xd8", 2);
// One 8 x 8 grey component, baseline (SOF0) or progressive (SOF2).
std::string frame(unsigned char sof) { return segment(sof, std::string("\x08\x00\x08\x00\x08\x01\x01\x11\x00", 9)); }
// A scan of the one component with DC table 0 and AC table 0, spectral range and approximation.
std::string scan(int start, int end, int high) {
    return segment(0xda, std::string("\x01\x01\x00", 3) + char(start) + char(end) + char(high << 4)) + "\x12\x34";
}

TEST(ImageChecks, JpegHuffmanTablesOfMoreThan256CodesAreRefused) {
    EXPECT_EQ(jpeg_check(kSoi + segment(0xc4, huffman_table(0, 0, 257))),
              "a JPEG Huffman table of 257 codes (at most 256; stb_image 2.27 would write past its table)");
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc0) + segment(0xc4, huffman_table(0, 0, 256) + huffman_table(1, 0, 12)) +
                         scan(0, 63, 0) + "\xff\xd9"),
              "");
}

TEST(ImageChecks, JpegScansWithoutTheirTablesAreRefused) {
    const std::string tables = segment(0xc4, huffman_table(0, 0, 12) + huffman_table(1, 0, 12));
    const std::string dc_only = segment(0xc4, huffman_table(0, 0, 12));
    const std::string refused =
        "a JPEG scan decodes with a Huffman table defined nowhere before it (stb_image 2.27 would read one it never "
        "set)";
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc0) + tables + scan(0, 63, 0) + "\xff\xd9"), "");
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc0) + dc_only + scan(0, 63, 0) + "\xff\xd9"), refused);
    // Defined after the scan is too late.
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc0) + scan(0, 63, 0) + tables + "\xff\xd9"), refused);
    // Progressive: a first DC scan needs only its DC table, a DC refinement
    // none, an AC scan its AC table.
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc2) + dc_only + scan(0, 0, 0) + scan(0, 0, 1) + "\xff\xd9"), "");
    EXPECT_EQ(jpeg_check(kSoi + frame(0xc2) + dc_only + scan(0, 0, 0) + scan(1, 5, 0) + "\xff\xd9"), refused);
}

TEST(ImageChecks, RealJpegPasses) {
    // assimp-testmodels' one JPEG (setup installs the package).
    std::ifstream in("/usr/share/assimp/models/glTF2/ClearCoat-glTF/PlasticWrap_normals.jpg", std::ios::binary);
    if (!in) GTEST_SKIP() << "assimp-testmodels is not installed";
    const std::string jpeg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(jpeg.size(), 1000u);
    EXPECT_EQ(jpeg_check(jpeg), "");
}

}  // namespace
}  // namespace fh
