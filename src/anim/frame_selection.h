// Which frames of a movie a run renders. A frame's number (and so its file,
// pipeline/frame_files.h) depends only on its global index, never on the
// range or shard that selected it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fh {

struct FrameRange {
    int begin = 0;  // [begin, end)
    int end = -1;   // -1: to the movie's end
};

struct Shard {
    int index = 0;  // K
    int count = 1;  // N: this shard renders frames i with i mod N == K
};

// Frames of [0, frame_count) in the range and the shard, in increasing order.
// A range reaching past the movie is an error (std::invalid_argument).
std::vector<int> select_frames(int frame_count, std::optional<FrameRange> range,
                               std::optional<Shard> shard);

// "A:B" (A to B-1, a Python slice), "A-B" (A to B inclusive, as POV-Ray's
// +SF/+EF and Blender's -s/-e), "A:" or "A-" (to the end) -> FrameRange; "K/N" -> Shard; std::invalid_argument on bad syntax or values.
FrameRange parse_range(const std::string& text);
Shard parse_shard(const std::string& text);

// A frame number, shard or count as text: digits only, at most
// kMaxFrameNumber. Empty when `text` is one (and `value` set), else what is
// wrong with it: "is not a whole number >= 0" or "is more than 1000000000".
inline constexpr long long kMaxFrameNumber = 1'000'000'000;
std::string frame_number_problem(const std::string& text, long long& value);

}  // namespace fh
