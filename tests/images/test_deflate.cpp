// The PNG writer's own deflate (images/deflate.h, images/huffman.h), checked by
// decoders that share no code with it: zlib's inflate for the stream and
// stb_image for whole PNG files.
#include <gtest/gtest.h>

#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include "images/deflate.h"
#include "images/huffman.h"
#include "images/png_writer.h"
#include "support/png_read.h"
#include "test_util.h"

namespace fh {
namespace {

// Sum of 2^-length over the used symbols, in units of 2^-15.
long long kraft(const std::vector<std::uint8_t>& lengths) {
    long long sum = 0;
    for (const std::uint8_t l : lengths)
        if (l) sum += 1LL << (15 - l);
    return sum;
}

TEST(Huffman, LengthsFormACompleteCodeWithinTheLimit) {
    // Frequencies from flat to Fibonacci-skewed (whose optimal code would be
    // 40 bits deep): the limit holds and the code stays complete.
    std::vector<std::vector<std::uint32_t>> cases = {{5, 5, 5, 5}, {1, 2}, {100, 1, 1, 1, 1, 1, 1}};
    std::vector<std::uint32_t> fib = {1, 1};
    while (fib.size() < 40) fib.push_back(fib[fib.size() - 1] + fib[fib.size() - 2]);
    cases.push_back(fib);
    std::vector<std::uint32_t> sparse(286, 0);
    sparse[0] = 1'000'000;
    sparse[7] = 3;
    sparse[285] = 1;
    cases.push_back(sparse);
    for (const auto& freq : cases) {
        const auto lengths = huffman_lengths(freq, 15);
        ASSERT_EQ(lengths.size(), freq.size());
        EXPECT_EQ(kraft(lengths), 1LL << 15) << "complete";
        for (size_t s = 0; s < freq.size(); ++s) {
            EXPECT_LE(lengths[s], 15);
            EXPECT_EQ(lengths[s] > 0, freq[s] > 0) << s;
            for (size_t t = 0; t < freq.size(); ++t)  // more frequent: never longer
                if (freq[s] > freq[t] && freq[t] > 0) EXPECT_LE(lengths[s], lengths[t]);
        }
    }
    // The 7-bit limit of the code-length alphabet, and Fibonacci past it.
    const auto seven = huffman_lengths(std::vector<std::uint32_t>(fib.begin(), fib.begin() + 19), 7);
    EXPECT_EQ(*std::max_element(seven.begin(), seven.end()), 7);
    EXPECT_EQ(kraft(seven), 1LL << 15);
}

TEST(Huffman, ALoneSymbolStillMakesACompleteCode) {
    // Decoders refuse an incomplete code-length code: two codes of one bit.
    const auto lengths = huffman_lengths(std::vector<std::uint32_t>{0, 0, 9, 0}, 7);
    EXPECT_EQ(lengths, (std::vector<std::uint8_t>{1, 0, 1, 0}));
    // An alphabet of one symbol has no second code to pair it with.
    EXPECT_EQ(huffman_lengths(std::vector<std::uint32_t>{4}, 7), (std::vector<std::uint8_t>{1}));
    EXPECT_EQ(huffman_lengths(std::vector<std::uint32_t>{0, 0, 0}, 7), (std::vector<std::uint8_t>{0, 0, 0}));
}

TEST(Huffman, CanonicalCodesArePrefixFreeAndRfcOrdered) {
    // RFC 1951's example: lengths (3, 3, 3, 3, 3, 2, 4, 4) give codes
    // 010 011 100 101 110 00 1110 1111 (stored bit-reversed).
    const std::vector<std::uint8_t> lengths = {3, 3, 3, 3, 3, 2, 4, 4};
    const auto codes = canonical_codes(lengths);
    const int expected[] = {0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111};
    for (size_t s = 0; s < lengths.size(); ++s) {
        int reversed = 0;
        for (int b = 0; b < lengths[s]; ++b) reversed |= ((codes[s] >> b) & 1) << (lengths[s] - 1 - b);
        EXPECT_EQ(reversed, expected[s]) << s;
    }
}

TEST(Deflate, Adler32MatchesZlib) {
    std::mt19937 rng(3);
    for (const size_t n : {0u, 1u, 1023u, 1024u, 1025u, 5552u, 100'000u}) {
        std::vector<std::uint8_t> data(n);
        for (auto& b : data) b = std::uint8_t(rng());
        if (n == 100'000) std::fill(data.begin(), data.end(), 255);  // the sums' worst case
        EXPECT_EQ(adler32(data), std::uint32_t(::adler32(1, data.data(), uInt(n)))) << n;
    }
}

std::vector<std::uint8_t> compress(std::span<const std::uint8_t> data) {
    std::vector<std::uint8_t> out;
    zlib_compress_runs(data, out);
    return out;
}

std::vector<std::uint8_t> inflate_all(const std::vector<std::uint8_t>& stream, size_t expected_size) {
    std::vector<std::uint8_t> out(expected_size + 16);
    uLongf size = uLongf(out.size());
    const int rc = ::uncompress(out.data(), &size, stream.data(), uLong(stream.size()));
    EXPECT_EQ(rc, Z_OK);  // zlib also checks the Adler-32
    out.resize(rc == Z_OK ? size : 0);
    return out;
}

TEST(Deflate, ZlibInflatesRunsOfEveryLengthBack) {
    // Runs around the match limits (3, 4, 258 and one or two more, 2 * 258
    // and around, longer ones), of many byte values, between literals.
    std::vector<std::uint8_t> data;
    int value = 0;
    for (const int run : {1, 2, 3, 4, 5, 10, 11, 257, 258, 259, 260, 261, 262, 516, 517, 518, 1000, 4096}) {
        data.insert(data.end(), size_t(run), std::uint8_t(value));
        data.push_back(std::uint8_t(value * 7 + 1));
        value = (value + 37) % 256;
    }
    EXPECT_EQ(inflate_all(compress(data), data.size()), data);
}

TEST(Deflate, ZlibInflatesNoiseEmptyAndConstantInputsBack) {
    std::mt19937 rng(5);
    std::vector<std::uint8_t> noise(200'000);
    for (auto& b : noise) b = std::uint8_t(rng());
    EXPECT_EQ(inflate_all(compress(noise), noise.size()), noise);
    const std::vector<std::uint8_t> empty;
    EXPECT_EQ(inflate_all(compress(empty), 0), empty);
    const std::vector<std::uint8_t> zeros(1'000'000, 0);
    const auto packed = compress(zeros);
    EXPECT_LT(packed.size(), 1000u);  // runs of 258 in a couple of bits each
    EXPECT_EQ(inflate_all(packed, zeros.size()), zeros);
    const std::vector<std::uint8_t> one = {42};
    EXPECT_EQ(inflate_all(compress(one), 1), one);
    // The stream is appended: what was there stays.
    std::vector<std::uint8_t> out = {1, 2, 3};
    zlib_compress_runs(one, out);
    EXPECT_EQ(std::vector<std::uint8_t>(out.begin(), out.begin() + 3), (std::vector<std::uint8_t>{1, 2, 3}));
    EXPECT_EQ(inflate_all(std::vector<std::uint8_t>(out.begin() + 3, out.end()), 1), one);
}

// Whole PNG files through stb_image's decoder (its own inflate).
TEST(Deflate, PngFilesDecodeToTheSamePixels) {
    std::mt19937 rng(7);
    const auto dir = test::temp_dir() / "deflate_png";
    std::filesystem::create_directories(dir);
    for (const auto [w, h] : {std::pair{1, 1}, {2, 3}, {3, 1}, {17, 9}, {800, 5}, {5, 300}}) {
        Image image(w, h);
        for (size_t i = 0; i < image.rgb.size(); ++i)  // smooth bands, flat runs and noise
            image.rgb[i] = std::uint8_t(i % 7 == 0 ? rng() : (i / 97) % 256);
        const std::string path = (dir / ("img_" + std::to_string(w) + "x" + std::to_string(h) + ".png")).string();
        write_png(path, image);
        const Image back = test::read_png(path);
        EXPECT_EQ(back.width, w);
        EXPECT_EQ(back.height, h);
        EXPECT_EQ(back.rgb, image.rgb) << w << "x" << h;
    }
}

}  // namespace
}  // namespace fh
