// The run's input files: one check before reading, and a list of what was
// read (by device and inode, so every name of a file is the same file).
#include "files/input_files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "text/input_error.h"

namespace fh {

namespace {

std::mutex g_mutex;
std::vector<std::pair<dev_t, ino_t>> g_read;  // guarded by g_mutex

std::string lowercase_first(std::string s) {
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

}  // namespace

std::string why_unreadable(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return errno == ENOENT ? "no such file" : lowercase_first(std::strerror(errno));
    if (S_ISDIR(st.st_mode)) return "is a folder";
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    if (::access(path.c_str(), R_OK) != 0) return lowercase_first(std::strerror(errno));
    return "";
}

void note_input_file(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return;
    const std::lock_guard lock(g_mutex);
    const std::pair<dev_t, ino_t> id{st.st_dev, st.st_ino};
    if (std::find(g_read.begin(), g_read.end(), id) == g_read.end()) g_read.push_back(id);
}

void check_not_an_input(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return;
    const std::lock_guard lock(g_mutex);
    if (std::find(g_read.begin(), g_read.end(), std::pair{st.st_dev, st.st_ino}) != g_read.end())
        throw InputError(path, "cannot write: it is a file this run reads");
}

}  // namespace fh
