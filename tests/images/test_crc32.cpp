// The PNG chunks' CRC-32 (png_crc32, zlib's crc32() behind stb_image_write's
// STBIW_CRC32 hook) against its check values, a bit-at-a-time reference, and
// in the chunks encode_png writes.
#include <gtest/gtest.h>

#include <random>
#include <string_view>
#include <vector>

#include "images/png_writer.h"

namespace fh::test {
namespace {

// The CRC-32 by its definition, one bit a step: shares no code with zlib's.
std::uint32_t reference_crc32(const std::uint8_t* p, size_t n) {
    std::uint32_t c = ~0u;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int bit = 0; bit < 8; ++bit) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

const std::uint8_t* bytes(std::string_view s) { return reinterpret_cast<const std::uint8_t*>(s.data()); }

std::uint32_t big_endian32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

TEST(Crc32, CheckValue) {
    // The CRC-32 catalogue's check: "123456789" -> 0xCBF43926; and PNG's
    // IEND chunk, whose CRC every PNG file ends with: AE 42 60 82.
    constexpr std::string_view digits = "123456789", iend = "IEND";
    EXPECT_EQ(png_crc32(bytes(digits), digits.size()), 0xCBF43926u);
    EXPECT_EQ(png_crc32(bytes(iend), iend.size()), 0xAE426082u);
    EXPECT_EQ(png_crc32(nullptr, 0), 0u);
}

TEST(Crc32, MatchesTheDefinitionAtEveryLengthAndAlignment) {
    std::mt19937 rng(7);
    std::vector<std::uint8_t> data(4096 + 16);
    for (auto& b : data) b = std::uint8_t(rng());
    for (const size_t start : {0u, 1u, 3u, 7u})
        for (const size_t n : {1u, 7u, 8u, 9u, 15u, 16u, 17u, 63u, 4096u}) {
            const std::uint8_t* p = data.data() + start;
            EXPECT_EQ(png_crc32(p, n), reference_crc32(p, n)) << start << " " << n;
        }
}

TEST(Crc32, EveryChunkEncodePngWritesCarriesItsCrc) {
    Image image(37, 23);
    std::mt19937 rng(11);
    for (auto& b : image.rgb) b = std::uint8_t(rng() % 4);  // runs and noise
    const std::vector<std::uint8_t> png = encode_png(image);
    size_t at = 8, chunks = 0;  // after the signature: length, type, data, CRC over type and data
    while (at + 12 <= png.size()) {
        const size_t len = big_endian32(&png[at]);
        ASSERT_LE(at + 12 + len, png.size());
        EXPECT_EQ(big_endian32(&png[at + 8 + len]), reference_crc32(&png[at + 4], 4 + len)) << "chunk " << chunks;
        at += 12 + len;
        ++chunks;
    }
    EXPECT_EQ(at, png.size());
    EXPECT_GE(chunks, 3u);  // IHDR, IDAT, IEND
}

}  // namespace
}  // namespace fh::test
