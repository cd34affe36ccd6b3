#include "anim/frame_selection.h"

#include <cerrno>
#include <cstdlib>
#include <stdexcept>

namespace fh {

namespace {
int parse_nonnegative(const std::string& s, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE || v < 0 || v > 1'000'000'000)
        throw std::invalid_argument(what + ": '" + s + "' is not a whole number >= 0");
    return int(v);
}
}  // namespace

FrameRange parse_range(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        throw std::invalid_argument("--range must look like A:B (frames A to B-1), got '" + text + "'");
    FrameRange r{parse_nonnegative(text.substr(0, colon), "--range start"),
                 parse_nonnegative(text.substr(colon + 1), "--range end")};
    if (r.begin >= r.end)
        throw std::invalid_argument("--range " + text + " is empty: A must be less than B");
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
    if (r.end > frame_count)
        throw std::invalid_argument("--range " + std::to_string(r.begin) + ":" +
                                    std::to_string(r.end) + " reaches past the movie's " +
                                    std::to_string(frame_count) + " frames");
    const Shard s = shard.value_or(Shard{0, 1});
    std::vector<int> frames;
    for (int i = r.begin; i < r.end; ++i)
        if (i % s.count == s.index) frames.push_back(i);
    return frames;
}

std::string frame_file_name(int frame, int frame_count) {
    size_t digits = std::to_string(frame_count > 0 ? frame_count - 1 : 0).size();
    if (digits < 4) digits = 4;
    std::string n = std::to_string(frame);
    if (n.size() < digits) n.insert(0, digits - n.size(), '0');
    return "frame_" + n + ".png";
}

}  // namespace fh
