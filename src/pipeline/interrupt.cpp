#include "pipeline/interrupt.h"

#include <cerrno>
#include <ctime>

#include <pthread.h>

namespace fh {

namespace {

std::atomic<int> g_signal{0};

sigset_t watched_signals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    return set;
}

}  // namespace

InterruptWatch::InterruptWatch(std::chrono::milliseconds grace, std::function<void(int)> on_overdue)
    : grace_(grace), on_overdue_(std::move(on_overdue)) {
    const sigset_t set = watched_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    thread_ = std::thread([this] { watch(); });
}

// The signals stay blocked: a signal after the run is ignored rather than
// killing a process that has finished its work.
InterruptWatch::~InterruptWatch() {
    stop_ = true;
    thread_.join();
}

void InterruptWatch::watch() {
    using Clock = std::chrono::steady_clock;
    const sigset_t set = watched_signals();
    Clock::time_point first{};
    bool overdue = false;
    while (!stop_) {
        // Wakes 50 times a second at most: to notice stop_ and the deadline.
        const timespec tick{0, 20'000'000};
        const int sig = sigtimedwait(&set, nullptr, &tick);
        if (sig > 0) {
            int expected = 0;
            if (g_signal.compare_exchange_strong(expected, sig)) first = Clock::now();
            else overdue = true;  // a second signal: stop now
        }
        if (g_signal != 0 && (overdue || Clock::now() - first >= grace_) && on_overdue_) {
            on_overdue_(g_signal);
            return;
        }
    }
}

bool interrupted() { return g_signal.load() != 0; }
int interrupt_signal() { return g_signal.load(); }

}  // namespace fh
