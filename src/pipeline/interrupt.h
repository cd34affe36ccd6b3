// SIGINT / SIGTERM during a long run. While an InterruptWatch lives, both
// signals are blocked in every thread and taken by its own watcher thread
// (sigtimedwait), so nothing runs in a signal handler. On the first signal
// interrupted() turns true: the frame loop stops taking new frames and lets
// the ones in flight finish, their files written whole or not at all. Should
// the run not have ended `grace` after the signal (a frame at many samples
// per pixel can take minutes), or should a second signal come, `on_overdue`
// is called on the watcher thread: it ends the process (after making sure no
// file is half written). So a run stops within about `grace`.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

#include <csignal>

namespace fh {

class InterruptWatch {
public:
    // Construct before starting any other thread: threads inherit the block.
    InterruptWatch(std::chrono::milliseconds grace, std::function<void(int signal)> on_overdue);
    ~InterruptWatch();
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

private:
    void watch();

    std::chrono::milliseconds grace_;
    std::function<void(int)> on_overdue_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

bool interrupted();
int interrupt_signal();  // the signal received, 0 if none

}  // namespace fh
