// Huffman codes as deflate (RFC 1951, section 3.2.2) wants them: code
// lengths no longer than a limit, and the canonical codes those lengths
// define.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace fh {

// Code lengths for symbols with these frequencies: optimal (Huffman), then
// limited to max_length by lengthening the deepest codes just enough and
// shortening others until the code is complete again (Kraft sum 1), as
// deflate encoders commonly do. A symbol of frequency 0 gets length 0; at
// least two symbols get a length (a lone symbol is paired with symbol 0 or 1),
// so the code is complete, as a decoder requires -- unless the alphabet has
// only one symbol, which then gets length 1.
std::vector<std::uint8_t> huffman_lengths(std::span<const std::uint32_t> freq, int max_length);

// The canonical code of each symbol for these lengths, bit-reversed, ready
// for a writer that packs bits from the least significant end.
std::vector<std::uint16_t> canonical_codes(std::span<const std::uint8_t> lengths);

}  // namespace fh
