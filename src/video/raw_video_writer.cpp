#include "video/raw_video_writer.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "video/yuv420.h"

namespace fh {

RawPixelFormat parse_raw_pixel_format(const std::string& name) {
    if (name == "rgb24") return RawPixelFormat::rgb24;
    if (name == "yuv420p") return RawPixelFormat::yuv420p;
    throw std::invalid_argument("unknown raw pixel format '" + name + "' (rgb24 or yuv420p)");
}

RawVideoWriter::RawVideoWriter(const std::string& path, int window, RawPixelFormat format)
    : name_(path == "-" ? "standard output" : path), window_(window < 1 ? 1 : window), format_(format) {
    // A closed pipe is an error to report (EPIPE), not a signal that kills us.
    std::signal(SIGPIPE, SIG_IGN);
    if (path == "-") {
        fd_ = STDOUT_FILENO;
    } else {
        fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd_ < 0)
            throw std::runtime_error("cannot write raw video to " + path + ": " + std::strerror(errno));
        owns_fd_ = true;
    }
}

RawVideoWriter::~RawVideoWriter() {
    if (owns_fd_) ::close(fd_);
}

void RawVideoWriter::put(int position, Image image) {
    Bytes frame = format_ == RawPixelFormat::yuv420p ? to_yuv420p(image) : std::move(image.rgb);
    std::unique_lock lock(mutex_);
    advanced_.wait(lock, [&] { return position < next_ + window_ || !error_.empty(); });
    if (!error_.empty()) throw std::runtime_error(error_);
    held_.emplace(position, std::move(frame));
    for (auto it = held_.find(next_); it != held_.end(); it = held_.find(next_)) {
        write_all(it->second);
        held_.erase(it);
        ++next_;
    }
    advanced_.notify_all();
}

void RawVideoWriter::fail(const std::string& why) {
    std::lock_guard lock(mutex_);
    if (error_.empty()) error_ = "raw video stopped: " + why;
    advanced_.notify_all();
}

void RawVideoWriter::write_all(const Bytes& frame) {
    const auto* p = frame.data();
    size_t left = frame.size();
    while (left > 0) {
        const ssize_t n = ::write(fd_, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_ = "cannot write raw video to " + name_ + ": " +
                     (errno == EPIPE ? std::string("the reader closed it (did the encoder fail?)")
                                     : std::string(std::strerror(errno)));
            advanced_.notify_all();
            throw std::runtime_error(error_);
        }
        p += n;
        left -= size_t(n);
    }
}

}  // namespace fh
