// Runs the real firsthit binary (or a script) and captures what it printed.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

// A fresh, empty folder under the system's temporary folder.
inline std::filesystem::path fresh_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("firsthit_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// command: a shell command line; stdout and stderr are captured to files.
inline CommandResult run_shell(const std::string& command) {
    static int n = 0;
    const auto dir = std::filesystem::temp_directory_path() / "firsthit_test_capture";
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

inline std::string source_path(const std::string& rel) {
    return std::string(FIRSTHIT_SOURCE_DIR) + "/" + rel;
}

}  // namespace fh::test
