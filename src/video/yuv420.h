// RGB to Y'CbCr 4:2:0 (planar, "yuv420p"): the form H.264 encoders take.
// `make movies` streams frames to ffmpeg already converted, so the encoder
// process -- one thread beside the render pool -- does not spend a second
// per movie converting them itself (docs/speed.md).
//
// The conversion is the one ffmpeg applies to RGB frames that carry no
// colour tags: BT.601, limited range (luma 16..235, chroma 16..240). Luma is
// computed with libswscale's fixed-point coefficients and its two roundings,
// so the Y plane is byte for byte the one `ffmpeg -pix_fmt yuv420p` makes
// (tests/video/test_yuv420.cpp checks all 2^24 colours against it). Chroma is
// the mean of each 2x2 block, centred on it as swscale's is; swscale
// filters vertically with a wider bicubic kernel, so at horizontal edges
// chroma may differ from ffmpeg's by a few levels.
//
// Odd sides: the chroma planes are ceil(w/2) x ceil(h/2), and a block past
// the right or bottom edge repeats the edge pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "render/image.h"

namespace fh {

// Y (w*h bytes), then Cb and Cr (ceil(w/2)*ceil(h/2) bytes each).
Bytes to_yuv420p(const Image& image);

// Size in bytes of one such frame.
size_t yuv420p_size(int width, int height);

}  // namespace fh
