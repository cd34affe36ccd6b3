// A zlib stream (RFC 1950) of one deflate block (RFC 1951) with Huffman codes
// made for the data, whose only matches are runs of a repeated byte
// (distance 1). PNG rows after the Sub filter are mostly such runs -- 77% of
// a frame's bytes are zeros, in runs -- so on the tracer's frames this is
// about 4x faster than zlib at level 1, for files a third larger (docs/speed.md):
// one pass to find the runs, one to write the codes, no hash chains.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace fh {

// Appends the stream to out.
void zlib_compress_runs(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& out);

// Adler-32 (RFC 1950) of data.
std::uint32_t adler32(std::span<const std::uint8_t> data);

}  // namespace fh
