// Scene and movie files read as text, checked before any parser sees them: regular files of bounded
// size, UTF-8 without control bytes, so bad input is refused at its byte, not misread.
#include "text/text_input.h"

#include <cerrno>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

#include <sys/stat.h>

#include "files/input_files.h"
#include "text/input_error.h"
#include "text/utf8.h"

namespace fh {

namespace {

std::string lowercase_first(std::string s) {
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

std::string hex_byte(unsigned char c) {
    static const char hex[] = "0123456789abcdef";
    return std::string("0x") + hex[c >> 4] + hex[c & 15];
}

InputError too_large(const std::string& file, std::size_t size, std::size_t max_bytes) {
    return InputError(file, "file too large: " + std::to_string(size) + " bytes (the limit is " +
                                std::to_string(max_bytes) + " bytes, " + std::to_string(max_bytes >> 20) + " MiB)");
}

}  // namespace

std::size_t utf8_length(const std::string& text, std::size_t i) {
    if (utf8_c1_control(text, i) && static_cast<unsigned char>(text[i + 1]) != 0x85) return 0;
    return utf8_sequence(text, i);
}

void check_input_text(const std::string& file, const std::string& text, std::size_t max_bytes) {
    if (text.size() > max_bytes) throw too_large(file, text.size(), max_bytes);
    int line = 1, column = 1;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            column = 1;
            ++i;
            continue;
        }
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f)
            throw InputError(file, line, column,
                             "binary data, not text: control byte " + hex_byte(c) +
                                 " (scene and movie files are UTF-8 text)");
        const std::size_t length = utf8_length(text, i);
        if (length == 0)
            throw InputError(file, line, column,
                             "not UTF-8 text: byte " + hex_byte(c) + " (scene and movie files are UTF-8 text)");
        i += length;
        ++column;
    }
}

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
    // Opening a folder succeeds on Linux and then reads nothing; a device or a
    // pipe may never end. Say why instead.
    if (const std::string why = why_unreadable(path); !why.empty())
        throw InputError(path, "cannot read file: " + why);
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(errno)));
    if (static_cast<unsigned long long>(st.st_size) > max_bytes) throw too_large(path, std::size_t(st.st_size), max_bytes);
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(errno)));
    // Until the end, or one byte past the limit should the file have grown since.
    std::string text(std::min<std::size_t>(std::size_t(st.st_size), max_bytes) + 1, '\0');
    std::size_t n = 0;
    while (n < text.size()) {
        const std::size_t got = std::fread(text.data() + n, 1, text.size() - n, f);
        n += got;
        if (got == 0 || n > max_bytes) break;
        if (n == text.size() && text.size() <= max_bytes) text.resize(std::min(2 * text.size(), max_bytes + 1));
    }
    const bool failed = std::ferror(f) != 0;
    const int read_errno = errno;
    std::fclose(f);
    if (failed) throw InputError(path, "cannot read file: " + lowercase_first(std::strerror(read_errno)));
    text.resize(n);
    note_input_file(path);
    check_input_text(path, text, max_bytes);
    return text;
}

}  // namespace fh
