#include "images/deflate.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "images/huffman.h"

namespace fh {

std::uint32_t adler32(std::span<const std::uint8_t> data) {
    // Per block of n bytes from (a, b): a += sum of the bytes, and b += n a +
    // sum of (n - i) byte_i -- two sums GCC vectorises. 1024 keeps them in 32 bits.
    constexpr std::uint32_t kMod = 65521;
    std::uint32_t a = 1, b = 0;
    const std::uint8_t* p = data.data();
    for (size_t left = data.size(); left > 0;) {
        const std::uint32_t n = std::uint32_t(std::min<size_t>(left, 1024));
        std::uint32_t sum = 0, weighted = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            sum += p[i];
            weighted += (n - i) * p[i];
        }
        b = (b + a * n + weighted) % kMod;
        a = (a + sum) % kMod;
        p += n;
        left -= n;
    }
    return (b << 16) | a;
}

namespace {

constexpr int kEndOfBlock = 256;
constexpr int kLiteralLengthSymbols = 286;
constexpr int kMaxMatch = 258;

// Deflate's length symbols (RFC 1951, 3.2.5): for each match length 3..258,
// its symbol and extra bits.
struct LengthCode {
    std::uint16_t symbol;
    std::uint8_t extra_bits;
    std::uint16_t extra;
};
constexpr std::array<LengthCode, kMaxMatch + 1> length_codes() {
    constexpr int base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                              31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    constexpr int extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                               2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    std::array<LengthCode, kMaxMatch + 1> t{};
    for (int i = 0; i < 29; ++i) {
        const int last = i == 28 ? 258 : base[i + 1] - 1;
        for (int len = base[i]; len <= last && len <= kMaxMatch; ++len)
            t[size_t(len)] = {std::uint16_t(257 + i), std::uint8_t(extra[i]), std::uint16_t(len - base[i])};
    }
    return t;
}
constexpr auto kLengthCodes = length_codes();

// A token: a literal byte (< 256), or 256 + the length of a match at
// distance 1 -- a run of the byte before it.
using Token = std::uint16_t;
constexpr int kTokenValues = 256 + kMaxMatch + 1;

// Literals and matches: each run of one byte value of length r >= 4 becomes
// the byte and matches of r - 1 bytes at distance 1 (at most 258 each).
// Counts each symbol in freq. The tokens go into `tokens` (reused storage,
// grown to data.size() + 1 when shorter); returns how many there are.
size_t tokenize(std::span<const std::uint8_t> data, std::uint32_t* freq, std::vector<Token>& tokens) {
    if (tokens.size() < data.size() + 1) tokens.resize(data.size() + 1);  // never shrunk: no re-zeroing
    Token* out = tokens.data();
    // Literals are counted in four tables, by position: a run of one value
    // would otherwise wait on its own increments.
    std::uint32_t literals[4][256] = {};
    const std::uint8_t* p = data.data();
    const size_t n = data.size();
    for (size_t i = 0; i < n;) {
        const std::uint8_t b = p[i];
        const std::uint64_t repeated = 0x0101010101010101ull * b;
        // Most bytes start no run of 4: a literal, without the run search.
        std::uint32_t next4;
        if (i + 4 > n || (std::memcpy(&next4, p + i, 4), next4 != std::uint32_t(repeated))) {
            *out++ = b;
            ++literals[i & 3][b];
            ++i;
            continue;
        }
        // The run's end: 8 bytes at a time while they all equal b, then the
        // first that differs (little-endian: the lowest differing byte).
        size_t j = i + 4;
        for (;;) {
            if (j + 8 > n) {
                while (j < n && p[j] == b) ++j;
                break;
            }
            std::uint64_t word;
            std::memcpy(&word, p + j, 8);
            if (const std::uint64_t differ = word ^ repeated) {
                j += size_t(__builtin_ctzll(differ) / 8);
                break;
            }
            j += 8;
        }
        size_t run = j - i;
        *out++ = b;
        ++literals[0][b];
        for (--run; run >= 3;) {
            const size_t m = std::min<size_t>(run, kMaxMatch);
            *out++ = Token(256 + m);
            ++freq[kLengthCodes[m].symbol];
            run -= m;
        }
        for (; run > 0; --run) {
            *out++ = b;
            ++literals[0][b];
        }
        i = j;
    }
    for (int v = 0; v < 256; ++v)
        freq[v] += literals[0][v] + literals[1][v] + literals[2][v] + literals[3][v];
    return size_t(out - tokens.data());
}

// Packs bits from the least significant end, as deflate stores them, into
// a buffer sized beforehand (with 8 bytes to spare at its end). No branch:
// every put stores 8 bytes and moves on by the whole bytes it completed.
class BitWriter {
public:
    explicit BitWriter(std::uint8_t* out) : out_(out) {}
    void put(std::uint64_t bits, int count) {  // count <= 32
        buffer_ |= bits << pending_;
        pending_ += count;
        std::memcpy(out_, &buffer_, 8);  // little-endian: the low bytes first
        const int done = pending_ >> 3;  // at most 4: pending_ < 8 + 32 here
        out_ += done;
        buffer_ >>= 8 * done;
        pending_ &= 7;
    }
    std::uint8_t* finish() { return out_ + (pending_ + 7) / 8; }  // the last byte, padded

private:
    std::uint8_t* out_;
    std::uint64_t buffer_ = 0;
    int pending_ = 0;
};

// The code lengths of the literal/length and distance codes, one sequence,
// with runs shortened by the code-length alphabet's symbols 16 (repeat the
// previous length 3-6 times), 17 (3-10 zeros) and 18 (11-138 zeros).
struct LengthSymbol {
    std::uint8_t symbol, extra_bits, extra;
};
std::vector<LengthSymbol> encode_lengths(const std::vector<std::uint8_t>& lengths) {
    std::vector<LengthSymbol> out;
    for (size_t i = 0; i < lengths.size();) {
        const std::uint8_t len = lengths[i];
        size_t run = 1;
        while (i + run < lengths.size() && lengths[i + run] == len) ++run;
        i += run;
        if (len == 0) {
            for (; run >= 11; run -= std::min<size_t>(run, 138))
                out.push_back({18, 7, std::uint8_t(std::min<size_t>(run, 138) - 11)});
            if (run >= 3) {
                out.push_back({17, 3, std::uint8_t(run - 3)});
                run = 0;
            }
            for (; run > 0; --run) out.push_back({0, 0, 0});
        } else {
            out.push_back({len, 0, 0});
            for (--run; run >= 3; run -= std::min<size_t>(run, 6))
                out.push_back({16, 2, std::uint8_t(std::min<size_t>(run, 6) - 3)});
            for (; run > 0; --run) out.push_back({len, 0, 0});
        }
    }
    return out;
}

}  // namespace

void zlib_compress_runs(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& out) {
    thread_local std::vector<Token> token_storage;  // reused: no fresh pages per frame
    std::array<std::uint32_t, kLiteralLengthSymbols> freq{};
    const size_t token_count = tokenize(data, freq.data(), token_storage);  // may grow the storage
    const std::span<const Token> tokens(token_storage.data(), token_count);
    freq[kEndOfBlock] = 1;
    const std::vector<std::uint8_t> lit_lengths = huffman_lengths(freq, 15);
    const std::vector<std::uint16_t> lit_codes = canonical_codes(lit_lengths);

    // Every token's bits, whole: a literal's code, or a match's length code,
    // its extra bits and the distance code (distance 1: code 0, one bit).
    struct Bits {
        std::uint32_t bits;
        std::uint32_t count;
    };
    std::array<Bits, kTokenValues> emit{};
    for (int v = 0; v < 256; ++v) emit[size_t(v)] = {lit_codes[size_t(v)], lit_lengths[size_t(v)]};
    for (int m = 3; m <= kMaxMatch; ++m) {
        const LengthCode& c = kLengthCodes[size_t(m)];
        const std::uint32_t code_len = lit_lengths[c.symbol];
        emit[size_t(256 + m)] = {lit_codes[c.symbol] | (std::uint32_t(c.extra) << code_len),
                                 code_len + c.extra_bits + 1};  // + the distance bit, 0
    }

    // The one distance (1) has code 0, one bit long: a single-code distance
    // tree as RFC 1951 asks for (one code of length one).
    int hlit = kLiteralLengthSymbols;
    while (hlit > 257 && lit_lengths[size_t(hlit) - 1] == 0) --hlit;
    std::vector<std::uint8_t> all_lengths(lit_lengths.begin(), lit_lengths.begin() + hlit);
    all_lengths.push_back(1);
    const std::vector<LengthSymbol> length_symbols = encode_lengths(all_lengths);
    std::array<std::uint32_t, 19> length_freq{};
    for (const LengthSymbol& s : length_symbols) ++length_freq[s.symbol];
    const std::vector<std::uint8_t> cl_lengths = huffman_lengths(length_freq, 7);
    const std::vector<std::uint16_t> cl_codes = canonical_codes(cl_lengths);
    static constexpr int kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    int hclen = 19;
    while (hclen > 4 && cl_lengths[size_t(kOrder[hclen - 1])] == 0) --hclen;

    // The block's size in bits, so the output is sized once: every length of
    // one length symbol takes the same bits, so the frequencies tell.
    size_t total_bits = 3 + 5 + 5 + 4 + 3 * size_t(hclen);
    for (const LengthSymbol& s : length_symbols) total_bits += cl_lengths[s.symbol] + s.extra_bits;
    for (int v = 0; v < 256; ++v) total_bits += size_t(freq[size_t(v)]) * lit_lengths[size_t(v)];
    total_bits += lit_lengths[kEndOfBlock];
    for (int m = 3; m <= kMaxMatch; ++m)
        if (m == 3 || kLengthCodes[size_t(m)].symbol != kLengthCodes[size_t(m) - 1].symbol)
            total_bits += size_t(freq[kLengthCodes[size_t(m)].symbol]) * emit[size_t(256 + m)].count;

    const size_t start = out.size();
    out.resize(start + 2 + (total_bits + 7) / 8 + 4 + 8);
    out[start] = 0x78;      // deflate, 32K window
    out[start + 1] = 0x01;  // no dictionary, "fastest" level; (0x78 << 8 | 0x01) % 31 == 0
    BitWriter bits(out.data() + start + 2);
    bits.put(1, 1);  // the final block
    bits.put(2, 2);  // dynamic Huffman codes
    bits.put(std::uint32_t(hlit - 257), 5);
    bits.put(0, 5);  // one distance code
    bits.put(std::uint32_t(hclen - 4), 4);
    for (int i = 0; i < hclen; ++i) bits.put(cl_lengths[size_t(kOrder[i])], 3);
    for (const LengthSymbol& s : length_symbols) {
        bits.put(cl_codes[s.symbol], cl_lengths[s.symbol]);
        if (s.extra_bits) bits.put(s.extra, s.extra_bits);
    }
    for (const Token t : tokens) bits.put(emit[t].bits, int(emit[t].count));
    bits.put(lit_codes[kEndOfBlock], lit_lengths[kEndOfBlock]);
    std::uint8_t* end = bits.finish();
    const std::uint32_t check = adler32(data);
    for (int shift = 24; shift >= 0; shift -= 8) *end++ = std::uint8_t(check >> shift);
    out.resize(size_t(end - out.data()));
}

}  // namespace fh
