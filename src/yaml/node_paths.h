// A movie's paths on the nodes of its glTF files (docs/format.md):
// `nodes.NAME.translation` (a point), `nodes.NAME.rotation` (a quaternion
// x, y, z, w of any non-zero length, made unit) and `nodes.NAME.scale` (a
// number or three, none zero). Each is a plain value, `{value: ...}` or
// `{keyframes: [...], interpolation: step|linear}`, and becomes a glTF
// sampler of its own (anim/sampler.h: a rotation by slerp on the shorter
// arc) applied after the file's animations: a path overrides the file's
// channel on the same node and property.
#pragma once

#include <string>

#include "anim/movie.h"
#include "yaml/map_reader.h"

namespace fh {

bool is_node_path(const std::string& key);

NodeChannel read_node_path(const YamlReader& r, const MapReader::Entry& entry, const Movie& movie);

}  // namespace fh
