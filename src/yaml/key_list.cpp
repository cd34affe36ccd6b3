#include "yaml/key_list.h"

#include <algorithm>
#include <climits>
#include <sstream>

#include "yaml/map_reader.h"

namespace fh {

namespace {

// 301, 7.5, 0.333333: a number as people write it.
std::string number_text(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

}  // namespace

std::vector<KeyNode> read_key_list(const YamlReader& r, const YAML::Node& list, const Movie& movie) {
    r.expect_list(list, "'keyframes'");
    if (list.size() == 0) r.fail(list, "'keyframes' must have at least one key");
    std::vector<KeyNode> keys;
    const int n = movie.frame_count();
    for (const YAML::Node& item : list) {
        const MapReader key(r, item, "keyframe", {"frame", "time", "value"});
        if (key.has("frame") == key.has("time"))
            r.fail(item, "a keyframe needs 'frame' (a frame index) or 'time' (seconds), one of them");
        const bool timed = key.has("time");
        const YAML::Node at = key.value(timed ? "time" : "frame");
        const double frame = timed ? key.number_at_least("time", 0) * movie.fps : key.integer("frame", 0, INT_MAX);
        // The end is frame n, or `seconds` where fps x seconds is no whole
        // number (fps 3, seconds 1.1: time 1.1 is frame 3.3); a millionth
        // of it is rounding, as in a time written 2.0000001.
        const double end = std::max(double(n), movie.fps * movie.seconds);
        if (frame > end + 1e-6 * end)
            r.fail(at, "keyframe at " + (timed ? "time " + number_text(frame / movie.fps) + " s (frame " : "frame ") +
                           number_text(frame) + (timed ? ")" : "") + " is past the movie's end (frame " +
                           number_text(end) + ", " + number_text(movie.seconds) + " s)");
        if (!keys.empty() && frame == keys.back().frame) r.fail(at, "two keyframes at frame " + number_text(frame));
        if (!keys.empty() && frame < keys.back().frame)
            r.fail(at, "keyframes must be in increasing order: this one is at frame " + number_text(frame) +
                           ", the one before at frame " + number_text(keys.back().frame));
        keys.push_back({frame, key.value("value")});
    }
    return keys;
}

}  // namespace fh
