// CRC-32 (io/crc32.h) against its check value and against zlib's crc32.
#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <string_view>
#include <vector>

#include "io/crc32.h"

namespace fh::test {
namespace {

TEST(Crc32, CheckValue) {
    // The CRC-32 catalogue's check: "123456789" -> 0xCBF43926; and PNG's
    // IEND chunk, whose CRC every PNG file ends with: AE 42 60 82.
    constexpr std::string_view digits = "123456789", iend = "IEND";
    EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(digits.data()), digits.size()}), 0xCBF43926u);
    EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(iend.data()), iend.size()}), 0xAE426082u);
    EXPECT_EQ(crc32({}), 0u);
}

TEST(Crc32, MatchesZlibAtEveryLengthAndAlignment) {
    std::mt19937 rng(7);
    std::vector<std::uint8_t> data(4096 + 16);
    for (auto& b : data) b = std::uint8_t(rng());
    for (const size_t start : {0u, 1u, 3u, 7u})
        for (const size_t n : {1u, 7u, 8u, 9u, 15u, 16u, 17u, 63u, 4096u}) {
            const std::uint8_t* p = data.data() + start;
            EXPECT_EQ(crc32({p, n}), std::uint32_t(::crc32(0, p, uInt(n)))) << start << " " << n;
        }
}

}  // namespace
}  // namespace fh::test
