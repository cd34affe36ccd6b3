// Writing a file so that it is whole or absent (write under a temporary name, fsync, rename), and
// the housekeeping around it: stale temporaries, output places checked before rendering.
#include "files/atomic_file.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cctype>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <sys/types.h>
#include <unistd.h>

#include "text/input_error.h"

namespace fh {

namespace {

namespace fs = std::filesystem;

const std::string& host_name() {
    static const std::string name = [] {
        char buf[HOST_NAME_MAX + 1] = {};
        std::string h = gethostname(buf, sizeof buf - 1) == 0 ? buf : "";
        // Only characters that are safe in a file name.
        for (char& c : h)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
        return h.empty() ? std::string("host") : h;
    }();
    return name;
}

std::string lower_strerror(int e) {
    std::string s = std::strerror(e);
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

// Parses "NAME.tmp-HOST-PID-N" into HOST and PID; false when it is not one.
bool parse_temporary(const std::string& file, std::string& host, long long& pid) {
    const auto tmp = file.rfind(".tmp-");
    if (tmp == std::string::npos) return false;
    const std::string rest = file.substr(tmp + 5);
    const auto last = rest.rfind('-');
    if (last == std::string::npos || last == 0) return false;
    const auto mid = rest.rfind('-', last - 1);
    if (mid == std::string::npos || mid == 0) return false;
    const std::string n = rest.substr(last + 1), p = rest.substr(mid + 1, last - mid - 1);
    const auto digits = [](const std::string& t) {
        return !t.empty() && t.size() < 12 &&
               std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!digits(n) || !digits(p)) return false;
    host = rest.substr(0, mid);
    pid = std::stoll(p);
    return true;
}

bool process_alive(long long pid) {
    if (pid <= 0 || pid > INT_MAX) return false;
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

}  // namespace

std::string temporary_name(const std::string& path, unsigned n) {
    return path + ".tmp-" + host_name() + "-" + std::to_string(getpid()) + "-" + std::to_string(n);
}

void write_file_atomic(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    static std::atomic<unsigned> counter{0};
    const std::string tmp = temporary_name(path, counter.fetch_add(1));
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path + ": " + lower_strerror(errno));
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0;
    int error = ok ? 0 : errno;
    // On disk before the rename, so the name never points at missing data.
    if (ok && ::fsync(fileno(f)) != 0 && errno != EINVAL && errno != EROFS) {
        ok = false;
        error = errno;
    }
    if (std::fclose(f) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (!ok) {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write " + path + ": " + lower_strerror(error));
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = errno;
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write " + path + ": " + lower_strerror(e));
    }
}

int remove_stale_temporaries(const std::string& dir, double max_age_seconds) {
    int removed = 0;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::string host;
        long long pid = 0;
        if (!parse_temporary(it->path().filename().string(), host, pid)) continue;
        if (!it->is_regular_file(ec)) continue;
        bool stale = host == host_name() && (pid == getpid() || !process_alive(pid));
        if (!stale) {
            const auto modified = fs::last_write_time(it->path(), ec);
            stale = !ec && std::chrono::duration<double>(now - modified).count() > max_age_seconds;
        }
        std::error_code remove_ec;
        if (stale && fs::remove(it->path(), remove_ec)) ++removed;
    }
    return removed;
}

namespace {

// The folder must exist, be a folder and be writable.
void check_folder(const std::string& what, const fs::path& folder) {
    std::error_code ec;
    const fs::file_status st = fs::status(folder, ec);
    if (!fs::exists(st)) throw InputError(what, "cannot write: folder '" + folder.string() + "' does not exist");
    if (!fs::is_directory(st)) throw InputError(what, "cannot write: '" + folder.string() + "' is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(what, "cannot write: folder '" + folder.string() + "': " + lower_strerror(errno));
    // access() answers from the permission bits, and root passes them where
    // creating a file still fails (/sys, a read-only mount): so create one,
    // named as write_file_atomic's temporaries (a killed run's is cleaned up).
    const std::string probe = temporary_name((folder / ".firsthit-probe").string(), UINT_MAX);
    std::FILE* f = std::fopen(probe.c_str(), "wb");
    if (!f) throw InputError(what, "cannot write: folder '" + folder.string() + "': " + lower_strerror(errno));
    std::fclose(f);
    std::remove(probe.c_str());
}

}  // namespace

void check_output_file(const std::string& path) {
    if (path.empty()) throw UsageError("an output file name is empty");
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path, "cannot write: is a folder");
    const fs::path parent = fs::path(path).parent_path();
    check_folder(path, parent.empty() ? fs::path(".") : parent);
}

void check_stream_output(const std::string& path) {
    if (path == "-") return;
    if (path.empty()) throw UsageError("an output file name is empty");
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_directory(st) && !fs::is_regular_file(st)) {
        if (::access(path.c_str(), W_OK) != 0) throw InputError(path, "cannot write: " + lower_strerror(errno));
        return;
    }
    check_output_file(path);
}

void prepare_output_folder(const std::string& dir) {
    std::error_code ec;
    if (dir.empty()) throw InputError(dir, "cannot write: empty folder name");
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create output folder: " + lower_strerror(ec.value()));
    check_folder(dir, dir);
}

}  // namespace fh
