// Small helpers shared by tests: a private temporary folder and files in it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fh::test {

// A folder of this test process, created on first use and removed at exit.
// One per process because ctest runs tests as separate processes at once.
inline const std::filesystem::path& temp_dir() {
    struct Dir {
        std::filesystem::path path;
        Dir() {
            path = std::filesystem::temp_directory_path() / ("firsthit_test_" + std::to_string(::getpid()));
            std::filesystem::remove_all(path);
            std::filesystem::create_directories(path);
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Dir dir;
    return dir.path;
}

// Writes `content` to temp_dir()/name (folders created as needed); returns its path.
inline std::string write_temp_file(const std::string& name, const std::string& content) {
    const std::filesystem::path path = temp_dir() / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << content;
    return path.string();
}

}  // namespace fh::test
