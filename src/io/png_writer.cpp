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
#include <stdexcept>

#include <sys/types.h>
#include <unistd.h>

#include "io/input_error.h"

#include <zlib.h>

#include "io/deflate.h"

namespace fh {

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

// A chunk: length, type, data, and the CRC-32 of type and data.
void put_chunk(std::vector<std::uint8_t>& out, const char* type, std::span<const std::uint8_t> data) {
    put_u32(out, std::uint32_t(data.size()));
    const size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    if (!data.empty()) out.insert(out.end(), data.begin(), data.end());
    put_u32(out, std::uint32_t(crc32(0, out.data() + start, uInt(out.size() - start))));
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
    // Every row with the Sub filter (each byte minus the one a pixel to its
    // left): the tracer's smooth shading turns into runs of 0, which
    // zlib_compress_runs codes in a few bits each.
    const size_t stride = size_t(image.width) * 3;
    thread_local std::vector<std::uint8_t> rows;  // reused: no fresh pages per frame
    rows.resize((stride + 1) * size_t(image.height));
    for (int y = 0; y < image.height; ++y) {
        const std::uint8_t* in = image.pixel(0, y);
        std::uint8_t* out = rows.data() + size_t(y) * (stride + 1);
        out[0] = 1;  // Sub
        for (size_t i = 0; i < std::min<size_t>(3, stride); ++i) out[1 + i] = in[i];
        for (size_t i = 3; i < stride; ++i) out[1 + i] = std::uint8_t(in[i] - in[i - 3]);
    }
    std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};  // the signature
    png.reserve(rows.size() / 4);
    std::vector<std::uint8_t> header;
    put_u32(header, std::uint32_t(image.width));
    put_u32(header, std::uint32_t(image.height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
    put_chunk(png, "IHDR", header);
    // IDAT, compressed in place: length (filled in after), type, stream, CRC.
    const size_t length_at = png.size();
    put_u32(png, 0);
    png.insert(png.end(), {'I', 'D', 'A', 'T'});
    zlib_compress_runs(rows, png);
    const std::uint32_t length = std::uint32_t(png.size() - length_at - 8);
    for (int k = 0; k < 4; ++k) png[length_at + size_t(k)] = std::uint8_t(length >> (24 - 8 * k));
    put_u32(png, std::uint32_t(crc32(0, png.data() + length_at + 4, uInt(length + 4))));
    put_chunk(png, "IEND", std::span<const std::uint8_t>());
    return png;
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
