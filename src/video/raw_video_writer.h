// Frames, in order, as raw video to a pipe or file: RGB24 (width * height * 3
// bytes each), what an encoder reads with `ffmpeg -f rawvideo -pix_fmt rgb24
// -s WxH -i -`, or converted to yuv420p (video/yuv420.h) by the worker that
// rendered the frame. `make movies` pipes `firsthit frames --raw-video -`
// into ffmpeg, so encoding runs while frames are rendered instead of after.
//
// Workers finish frames a little out of order; each frame is held until all
// before it are written, and a worker that gets too far ahead waits, so at
// most `window` frames are held. The first failed write (the encoder exited:
// EPIPE) is thrown to its writer and to every later put.
#pragma once

#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "render/image.h"

namespace fh {

enum class RawPixelFormat { rgb24, yuv420p };

// "rgb24" or "yuv420p"; std::invalid_argument naming the choices otherwise.
RawPixelFormat parse_raw_pixel_format(const std::string& name);

class RawVideoWriter {
public:
    // path "-" is standard output; anything else is created or truncated.
    RawVideoWriter(const std::string& path, int window, RawPixelFormat format = RawPixelFormat::rgb24);
    ~RawVideoWriter();
    RawVideoWriter(const RawVideoWriter&) = delete;
    RawVideoWriter& operator=(const RawVideoWriter&) = delete;

    // The frame at this position of the stream (0, 1, 2, ...). Converted
    // (yuv420p) by the calling thread, before it waits for its turn.
    void put(int position, Image image);

    // A frame will never come (its worker failed): release the waiting ones.
    void fail(const std::string& why);

private:
    void write_all(const Bytes& frame);  // with mutex_ held

    std::string name_;
    int fd_ = -1;
    bool owns_fd_ = false;
    int window_;
    RawPixelFormat format_;
    std::mutex mutex_;
    std::condition_variable advanced_;
    std::map<int, Bytes> held_;  // frames in the stream's format
    int next_ = 0;
    std::string error_;  // set once a write failed
};

}  // namespace fh
