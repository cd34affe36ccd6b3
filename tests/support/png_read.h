// Reading PNGs back in tests (stb_image).
#pragma once

#include <string>

#include "render/image.h"

namespace fh::test {

// An RGB image; width 0 when the file cannot be read.
Image read_png(const std::string& path);

// Largest per-channel difference, and how many channels differ at all.
struct ImageDiff {
    int max_abs = 0;
    size_t differing = 0;
};
ImageDiff compare(const Image& a, const Image& b);

}  // namespace fh::test
