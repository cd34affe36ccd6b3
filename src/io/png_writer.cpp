#include "io/png_writer.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cctype>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>

#include <sys/types.h>
#include <unistd.h>

#include "io/input_error.h"

#include "io/crc32.h"
#include "io/deflate.h"

// stb_image_write lays out the PNG (the Sub filter on every row, chunks, CRCs)
// and is compiled here, privately; the deflate inside is ours,
// zlib_compress_runs, through stb's hook for it: after the Sub filter a
// frame is mostly runs of 0, which it codes ~4x faster than zlib at level 1
// (README, Speed). The chunks' CRCs are ours too (io/crc32.h), 8 bytes a step.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#define STBIW_ZLIB_COMPRESS fh_png_deflate
static unsigned char* fh_png_deflate(unsigned char* data, int data_len, int* out_len, int quality);
#define STBIW_CRC32(buffer, len) fh::crc32(std::span<const std::uint8_t>(buffer, size_t(len)))
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

// stb frees the result with free(), so it is allocated with malloc(). No
// exception may cross stb's C code (it would leak stb's buffers): running out
// of memory is a null result, which stb reports as a failure.
static unsigned char* fh_png_deflate(unsigned char* data, int data_len, int* out_len, int) {
    thread_local std::vector<std::uint8_t> stream;  // reused: no fresh pages per frame
    stream.clear();
    try {
        fh::zlib_compress_runs(std::span<const std::uint8_t>(data, size_t(data_len)), stream);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
    auto* out = static_cast<unsigned char*>(std::malloc(stream.size()));
    if (!out) return nullptr;
    std::memcpy(out, stream.data(), stream.size());
    *out_len = int(stream.size());
    return out;
}

// Every row with the Sub filter (each byte minus the one a pixel to its
// left): the tracer's smooth shading becomes runs of 0, as small as stb's
// choice per row and twice as fast to make. Set once, before any thread starts.
static const bool kPngFilterChosen = (stbi_write_force_png_filter = 1, true);

namespace fh {

std::vector<std::uint8_t> encode_png(const Image& image) {
    std::vector<std::uint8_t> out;
    auto append = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<std::uint8_t>*>(ctx);
        const auto* p = static_cast<const std::uint8_t*>(data);
        v->insert(v->end(), p, p + size);
    };
    if (!stbi_write_png_to_func(append, &out, image.width, image.height, 3, image.rgb.data(),
                                image.width * 3))
        throw std::runtime_error("PNG encoding failed: out of memory for a " + std::to_string(image.width) +
                                 "x" + std::to_string(image.height) + " image");
    return out;
}

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
}

}  // namespace

void check_output_file(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path, "cannot write: is a folder");
    const fs::path parent = fs::path(path).parent_path();
    check_folder(path, parent.empty() ? fs::path(".") : parent);
}

void prepare_output_folder(const std::string& dir) {
    std::error_code ec;
    if (dir.empty()) throw InputError(dir, "cannot write: empty folder name");
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create output folder: " + lower_strerror(ec.value()));
    check_folder(dir, dir);
}

void write_png(const std::string& path, const Image& image) {
    write_file_atomic(path, encode_png(image));
}

bool is_complete_png(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return false;
    const std::streamoff size = in.tellg();
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    // The IEND chunk: zero length, type, CRC.
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (size < std::streamoff(sizeof signature + sizeof iend)) return false;
    unsigned char head[8], tail[12];
    in.seekg(0);
    in.read(reinterpret_cast<char*>(head), sizeof head);
    in.seekg(size - std::streamoff(sizeof tail));
    in.read(reinterpret_cast<char*>(tail), sizeof tail);
    return in && std::memcmp(head, signature, sizeof head) == 0 &&
           std::memcmp(tail, iend, sizeof tail) == 0;
}

}  // namespace fh
