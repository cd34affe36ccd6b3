// A movie's `keyframes:` list as frames and values: each key at `frame:` or
// `time:` (seconds: frame = time * fps), in increasing order, inside the
// movie (0 <= frame <= its frame count). The values stay YAML for the caller
// to read as its property wants (a vector, a number, a quaternion).
#pragma once

#include <vector>

#include "anim/movie.h"
#include "yaml/yaml_reader.h"

namespace fh {

struct KeyNode {
    double frame;
    YAML::Node value;
};

std::vector<KeyNode> read_key_list(const YamlReader& r, const YAML::Node& list, const Movie& movie);

}  // namespace fh
