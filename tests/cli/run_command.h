// Runs the real firsthit binary (or a script) and captures what it printed.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "sanitizer_build.h"
#include "test_util.h"

extern char** environ;

namespace fh::test {

struct CommandResult {
    int status = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A fresh, empty folder in this test process's own temporary folder
// (test_util.h: removed at exit), so tests running at the same time, in
// this checkout or another, never share one.
inline std::filesystem::path fresh_dir(const std::string& name) {
    const auto dir = temp_dir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// command: a shell command line; stdout and stderr are captured to files.
inline CommandResult run_shell(const std::string& command) {
    static int n = 0;
    const auto dir = temp_dir() / "capture";
    std::filesystem::create_directories(dir);
    const auto out = dir / ("out" + std::to_string(n));
    const auto err = dir / ("err" + std::to_string(n++));
    const int raw = std::system((command + " >" + out.string() + " 2>" + err.string()).c_str());
    CommandResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

inline CommandResult run_firsthit(const std::string& args) {
    return run_shell(std::string(FIRSTHIT_BINARY) + " " + args);
}

// firsthit started in the background (no shell between: the pid is its own),
// stdout and stderr to files; for tests that send it signals.
struct Background {
    pid_t pid = -1;
    std::filesystem::path out, err;
};

inline Background spawn_firsthit(const std::vector<std::string>& args, const std::filesystem::path& log_dir) {
    Background b;
    b.out = log_dir / "stdout.txt";
    b.err = log_dir / "stderr.txt";
    std::vector<std::string> words{FIRSTHIT_BINARY};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, b.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, b.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (posix_spawn(&b.pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) b.pid = -1;
    posix_spawn_file_actions_destroy(&actions);
    return b;
}

// Waits up to `timeout` for the process to end; its raw wait status, or -1
// if it is still running then.
inline int wait_for(pid_t pid, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int status = 0;
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid) return status;
        if (r < 0 || std::chrono::steady_clock::now() >= end) return -1;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

// How many threads the process runs (from /proc); 0 when it is gone.
inline int thread_count(pid_t pid) {
    std::error_code ec;
    int n = 0;
    for (std::filesystem::directory_iterator it("/proc/" + std::to_string(pid) + "/task", ec), end;
         !ec && it != end; it.increment(ec))
        ++n;
    return n;
}

// Tests that time things run slower under the sanitizers.
inline constexpr int kSlowdown = kMallocSanitized ? 4 : 1;

inline std::string source_path(const std::string& rel) {
    return std::string(FIRSTHIT_SOURCE_DIR) + "/" + rel;
}

// scripts/NAME with the arguments, driving this build's firsthit.
inline CommandResult run_script(const std::string& name, const std::string& args) {
    return run_shell("FIRSTHIT=" + std::string(FIRSTHIT_BINARY) + " " + source_path("scripts/" + name) + " " + args);
}

}  // namespace fh::test
