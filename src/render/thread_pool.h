// A fixed pool of worker threads that runs an indexed loop: tasks 0..n-1 are
// taken in order from one atomic counter, so a fast worker takes more of them
// and no thread waits while work is left. The calling thread works too.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fh {

class ThreadPool {
public:
    // threads <= 0: one per core.
    explicit ThreadPool(int threads = 0);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int size() const { return int(workers_.size()) + 1; }

    // Calls fn(task, worker) for every task in [0, count), worker in [0, size()).
    // Returns when all are done; rethrows the first exception a task threw
    // (the tasks not yet started are then skipped).
    void parallel_for(int count, const std::function<void(int task, int worker)>& fn);

    static int hardware_threads();

private:
    void worker_loop(int worker);
    void run_tasks(int worker);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(int, int)>* job_ = nullptr;
    int count_ = 0;
    std::atomic<int> next_{0};
    int busy_ = 0;             // workers still inside the current job
    unsigned generation_ = 0;  // bumped for each job
    bool stopping_ = false;
    std::exception_ptr error_;
};

}  // namespace fh
