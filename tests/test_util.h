// Small helpers shared by tests: a private temporary folder and files in it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "text/input_error.h"

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

// The formatted InputError that check(path) throws, the path shown as
// FILE; "(no error)" when it throws none.
template <typename Check>
std::string check_error(const std::string& path, Check&& check) {
    try {
        check(path);
    } catch (const InputError& e) {
        std::string s = e.formatted();
        if (s.rfind(path, 0) == 0) s.replace(0, path.size(), "FILE");
        return s;
    }
    return "(no error)";
}

// The same for `content` written to temp_dir()/name.
template <typename Check>
std::string file_check_error(const std::string& name, const std::string& content, Check&& check) {
    return check_error(write_temp_file(name, content), check);
}

}  // namespace fh::test
