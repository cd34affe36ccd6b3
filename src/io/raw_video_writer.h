// Frames, in order, as raw RGB24 (width * height * 3 bytes each) to a pipe or
// file: what an encoder reads with `ffmpeg -f rawvideo -pix_fmt rgb24 -s WxH
// -i -`. `make movies` pipes `firsthit frames --raw-video -` into ffmpeg, so
// encoding runs while frames are rendered instead of after (issue 7).
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

#include "render/image.h"

namespace fh {

class RawVideoWriter {
public:
    // path "-" is standard output; anything else is created or truncated.
    RawVideoWriter(const std::string& path, int window);
    ~RawVideoWriter();
    RawVideoWriter(const RawVideoWriter&) = delete;
    RawVideoWriter& operator=(const RawVideoWriter&) = delete;

    // The frame at this position of the stream (0, 1, 2, ...).
    void put(int position, Image image);

    // A frame will never come (its worker failed): release the waiting ones.
    void fail(const std::string& why);

private:
    void write_all(const Image& image);  // with mutex_ held

    std::string name_;
    int fd_ = -1;
    bool owns_fd_ = false;
    int window_;
    std::mutex mutex_;
    std::condition_variable advanced_;
    std::map<int, Image> held_;
    int next_ = 0;
    std::string error_;  // set once a write failed
};

}  // namespace fh
