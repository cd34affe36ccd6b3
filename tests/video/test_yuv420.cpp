// RGB to yuv420p (video/yuv420.h): BT.601 limited-range values worked out by
// hand, the planes' layout with odd sides, and ffmpeg's own conversion as
// the reference it must agree with.
#include <gtest/gtest.h>

#include <cstdlib>

#include "anim/movie.h"
#include "cli/run_command.h"
#include "yaml/movie_loader.h"
#include "video/yuv420.h"
#include "render/render.h"

namespace fh::test {
namespace {

Image filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image im(w, h);
    for (size_t i = 0; i < im.rgb.size(); i += 3) im.rgb[i] = r, im.rgb[i + 1] = g, im.rgb[i + 2] = b;
    return im;
}

struct Yuv {
    int y, u, v;
};
Yuv first_pixel(const Image& im) {
    const auto out = to_yuv420p(im);
    const size_t luma = size_t(im.width) * size_t(im.height), chroma = (out.size() - luma) / 2;
    return {out[0], out[luma], out[luma + chroma]};
}

TEST(Yuv420, Bt601LimitedRangeValues) {
    // Y = 16 + (65.481 R + 128.553 G + 24.966 B) / 255,
    // Cb = 128 + (-37.797 R - 74.203 G + 112 B) / 255,
    // Cr = 128 + (112 R - 93.786 G - 18.214 B) / 255.
    const auto white = first_pixel(filled(2, 2, 255, 255, 255));
    EXPECT_EQ(white.y, 235);  // 16 + 219
    EXPECT_EQ(white.u, 128);
    EXPECT_EQ(white.v, 128);
    const auto black = first_pixel(filled(2, 2, 0, 0, 0));
    EXPECT_EQ(black.y, 16);
    EXPECT_EQ(black.u, 128);
    EXPECT_EQ(black.v, 128);
    const auto red = first_pixel(filled(2, 2, 255, 0, 0));
    EXPECT_EQ(red.y, 81);   // 81.48
    EXPECT_EQ(red.u, 90);   // 90.20
    EXPECT_EQ(red.v, 240);  // 128 + 112
    const auto blue = first_pixel(filled(2, 2, 0, 0, 255));
    EXPECT_EQ(blue.y, 41);  // 40.97
    EXPECT_EQ(blue.u, 240);
    EXPECT_EQ(blue.v, 110);  // 109.79
    // The report's grey floor, 130: Y = 16 + 219 * 130 / 255 = 127.65.
    EXPECT_EQ(first_pixel(filled(2, 2, 130, 130, 130)).y, 128);
}

TEST(Yuv420, ChromaIsTheMeanOfEach2x2BlockAndOddSidesRepeatTheEdge) {
    // 3 x 3: chroma is 2 x 2. Blue everywhere but the top-left pixel, white,
    // so the top-left block is 1/4 white, 3/4 blue; the blocks past the
    // right and bottom edges see only blue.
    Image im = filled(3, 3, 0, 0, 255);
    im.rgb[0] = im.rgb[1] = im.rgb[2] = 255;
    const auto out = to_yuv420p(im);
    ASSERT_EQ(out.size(), 9u + 2 * 4u);
    ASSERT_EQ(yuv420p_size(3, 3), out.size());
    EXPECT_EQ(out[0], 235);
    for (int i = 1; i < 9; ++i) EXPECT_EQ(out[size_t(i)], 41) << i;
    // Its mean is (63.75, 63.75, 255): Cb = 128 + 112 (255 - 63.75) / 255 = 212,
    // Cr = 128 - 18.214 (255 - 63.75) / 255 = 114.34.
    EXPECT_EQ(out[9], 212);
    EXPECT_EQ(out[13], 114);
    for (int i : {10, 11, 12}) EXPECT_EQ(out[size_t(i)], 240) << i;   // blue's Cb
    for (int i : {14, 15, 16}) EXPECT_EQ(out[size_t(i)], 110) << i;   // blue's Cr
}

TEST(Yuv420, AnEmptyImageIsEmptyPlanes) {
    EXPECT_TRUE(to_yuv420p(Image(0, 0)).empty());
    EXPECT_EQ(to_yuv420p(Image(0, 3)).size(), 0u);
}

// ffmpeg's rgb24 -> yuv420p conversion of `rgb` (w x h).
std::string ffmpeg_yuv(const Bytes& rgb, int w, int h, const std::string& name) {
    const auto dir = fresh_dir(name);
    std::ofstream(dir / "in.rgb", std::ios::binary)
        .write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
    const auto r = run_shell("ffmpeg -hide_banner -loglevel error -nostdin -y -f rawvideo -pix_fmt rgb24 -s " +
                             std::to_string(w) + "x" + std::to_string(h) + " -i " + (dir / "in.rgb").string() +
                             " -f rawvideo -pix_fmt yuv420p " + (dir / "out.yuv").string());
    EXPECT_EQ(r.status, 0) << r.err;
    return slurp(dir / "out.yuv");
}

TEST(Yuv420, LumaIsFfmpegsByteForByteForEveryColour) {
    // 4096 x 4096 pixels: every 24-bit colour once.
    Image im(4096, 4096);
    for (int y = 0; y < 4096; ++y)
        for (int x = 0; x < 4096; ++x) {
            std::uint8_t* p = im.pixel(x, y);
            p[0] = std::uint8_t(x & 255), p[1] = std::uint8_t(y & 255), p[2] = std::uint8_t((x >> 8) + 16 * (y >> 8));
        }
    const std::string reference = ffmpeg_yuv(im.rgb, 4096, 4096, "yuv_all");
    const auto ours = to_yuv420p(im);
    ASSERT_EQ(reference.size(), ours.size());
    size_t differing = 0;
    for (size_t i = 0; i < 4096u * 4096u; ++i) differing += std::uint8_t(reference[i]) != ours[i];
    EXPECT_EQ(differing, 0u);
}

TEST(Yuv420, ChromaOfAReportFrameIsWithinAFewLevelsOfFfmpegs) {
    const Movie movie = load_movie(source_path("animations/movie1.yaml"));
    const Image im = render_frame(movie.scene, camera_at(movie, 100), movie.settings, nullptr)
                         .image;
    const std::string reference = ffmpeg_yuv(im.rgb, im.width, im.height, "yuv_frame");
    const auto ours = to_yuv420p(im);
    ASSERT_EQ(reference.size(), ours.size());
    const size_t luma = size_t(im.width) * size_t(im.height);
    int max_diff = 0;
    double sum = 0;
    for (size_t i = 0; i < ours.size(); ++i) {
        const int d = std::abs(int(std::uint8_t(reference[i])) - int(ours[i]));
        if (i < luma) {
            EXPECT_EQ(d, 0) << "luma byte " << i;
            if (d) break;
        } else {
            max_diff = std::max(max_diff, d);
            sum += d;
        }
    }
    const double mean = sum / double(ours.size() - luma);
    // Measured: mean 0.13, max 8 (swscale's bicubic against the 2x2 mean at
    // the spheres' rims). A wrong matrix or range is off by tens of levels.
    EXPECT_LT(mean, 0.25);
    EXPECT_LE(max_diff, 10);
}

}  // namespace
}  // namespace fh::test
