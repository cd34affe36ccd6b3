// A placements table (`type: instances`, docs/format.md): one instance of a
// mesh per row of a CSV file, so a forest of 100,000 trees needs no
// 100,000-line YAML. A header row names the columns: tx, ty, tz (required),
// scale (uniform, not 0), axis_x, axis_y, axis_z and degrees (a rotation, all
// four or none), in any order; each row is scale, then rotate, then
// translate, as a surface's `transform`. Every mistake is an InputError at
// its line and column.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/instance.h"

namespace fh {

// A placements file may hold kMaxInstances rows (scene/instance.h), and be
// this large: 4 million rows of eight numbers written to full precision
// (up to 25 characters each) with room to spare.
inline constexpr std::size_t kMaxPlacementsBytes = std::size_t(1) << 30;

// The rows, each with its line in the file (for errors found later, once a
// row is composed with its set's transform and groups).
struct Placements {
    std::vector<Transform> rows;
    std::vector<int> lines;
};

Placements load_placements(const std::string& path);
// The same from text in memory (`file` names it in errors; tests).
Placements parse_placements(const std::string& text, const std::string& file);

}  // namespace fh
