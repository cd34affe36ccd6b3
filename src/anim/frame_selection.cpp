#include "anim/frame_selection.h"

#include <algorithm>
#include <stdexcept>

namespace fh {

std::string frame_number_problem(const std::string& text, long long& value) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return "is not a whole number >= 0";
    const size_t first = std::min(text.find_first_not_of('0'), text.size() - 1);  // leading zeros say nothing
    // More than ten digits would overflow stoll; they are past the limit anyway.
    const long long v = text.size() - first > 10 ? kMaxFrameNumber + 1 : std::stoll(text.substr(first));
    if (v > kMaxFrameNumber) return "is more than " + std::to_string(kMaxFrameNumber);
    value = v;
    return "";
}

namespace {
int parse_nonnegative(const std::string& s, const std::string& what) {
    long long v = 0;
    const std::string problem = frame_number_problem(s, v);
    if (!problem.empty()) throw std::invalid_argument(what + ": '" + s + "' " + problem);
    return int(v);
}
}  // namespace

FrameRange parse_range(const std::string& text) {
    const auto sep = text.find_first_of(":-", 1);  // from 1: "-1:4" is a negative start
    if (sep == std::string::npos)
        throw std::invalid_argument("--range must look like A-B (frames A to B), A:B (A to B-1) or A: (A to the end), got '" +
                                    text + "'");
    const bool inclusive = text[sep] == '-';
    FrameRange r{parse_nonnegative(text.substr(0, sep), "--range start"), -1};
    const std::string end = text.substr(sep + 1);
    if (end.empty()) return r;  // open: to the movie's end
    r.end = parse_nonnegative(end, "--range end") + (inclusive ? 1 : 0);
    if (r.begin >= r.end)
        throw std::invalid_argument("--range " + text + " is empty: " +
                                    (inclusive ? "A-B needs A <= B" : "A:B needs A < B (B is not rendered)"));
    return r;
}

Shard parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    if (slash == std::string::npos)
        throw std::invalid_argument("--shard must look like K/N (0 <= K < N), got '" + text + "'");
    Shard s{parse_nonnegative(text.substr(0, slash), "--shard K"),
            parse_nonnegative(text.substr(slash + 1), "--shard N")};
    if (s.count < 1 || s.index >= s.count)
        throw std::invalid_argument("--shard " + text + ": need 0 <= K < N");
    return s;
}

std::vector<int> select_frames(int frame_count, std::optional<FrameRange> range,
                               std::optional<Shard> shard) {
    FrameRange r = range.value_or(FrameRange{0, frame_count});
    if (r.end < 0) r.end = frame_count;
    if (r.begin >= frame_count || r.end > frame_count)
        throw std::invalid_argument("frame " + std::to_string(r.begin >= frame_count ? r.begin : r.end - 1) +
                                    " is past the movie's end: its " + std::to_string(frame_count) +
                                    " frames are 0 to " + std::to_string(frame_count - 1));
    const Shard s = shard.value_or(Shard{0, 1});
    std::vector<int> frames;
    for (int i = r.begin; i < r.end; ++i)
        if (i % s.count == s.index) frames.push_back(i);
    return frames;
}

}  // namespace fh
