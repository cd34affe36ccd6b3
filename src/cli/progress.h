// The progress line of long runs: frames done, frames per second, time left.
// Redrawn in place on a terminal, at most a few times a second.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>

namespace fh {

class Progress {
public:
    Progress(int total, bool show) : total_(total), show_(show), start_(Clock::now()) {}

    void frame_done() {
        std::lock_guard lock(mutex_);
        ++done_;
        if (!show_) return;
        const auto now = Clock::now();
        if (done_ < total_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
        last_draw_ = now;
        const double f = fps_locked();
        const double left = f > 0 ? (total_ - done_) / f : 0;
        std::fprintf(stderr, "\rframes %d/%d  %.1f frames/s  %d:%02d left ", done_, total_, f,
                     int(left) / 60, int(left) % 60);
        std::fflush(stderr);
    }

    void finish() {
        std::lock_guard lock(mutex_);
        if (show_ && done_ > 0 && !finished_) std::fprintf(stderr, "\n");
        finished_ = true;
    }

    // Safe to call from any thread, also while frames finish.
    int done() const {
        std::lock_guard lock(mutex_);
        return done_;
    }
    double seconds() const {
        return std::chrono::duration<double>(Clock::now() - start_).count();
    }
    double fps() const {
        std::lock_guard lock(mutex_);
        return fps_locked();
    }

private:
    using Clock = std::chrono::steady_clock;

    double fps_locked() const {
        const double s = seconds();
        return s > 0 ? done_ / s : 0;
    }

    mutable std::mutex mutex_;
    int total_;
    int done_ = 0;
    bool show_;
    bool finished_ = false;
    Clock::time_point start_;
    Clock::time_point last_draw_{};
};

}  // namespace fh
