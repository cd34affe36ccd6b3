#include "meshes/assimp_replay.h"

#include <cctype>
#include <cstring>

namespace fh::assimp_replay {

bool StreamBuffer::get_next_line(Buffer& buffer) {
    copied_ = false;
    length_ = 0;
    buffer.bytes.resize(cache_size_);
    if (cache_pos_ == cache_size_ || file_pos_ == 0)
        if (!read_next_block()) return false;
    if (is_line_end(cache(cache_pos_))) {
        while (cache(cache_pos_) != '\n') ++cache_pos_;
        ++cache_pos_;
        if (cache_pos_ == cache_size_ && !read_next_block()) return false;
    }
    std::size_t i = 0;
    ++lines_;
    while (!is_line_end(cache(cache_pos_))) {
        // assimp copies byte by byte, doubling the buffer whenever it is
        // full, and reads the next block after a block's last byte. The
        // bytes up to a line end or the block's end at once (past the
        // block, where the line-end skip above can leave it: one).
        copied_ = true;
        std::size_t end = cache_pos_ + 1;
        while (end < cache_size_ && !kLineEnds.at[static_cast<unsigned char>(cache_[end])]) ++end;
        const std::size_t n = end - cache_pos_;
        while (buffer.bytes.size() <= i + n) buffer.bytes.resize(buffer.bytes.size() * 2);
        std::memcpy(&buffer.bytes[i], &cache_[cache_pos_], n);
        i += n;
        length_ = i;
        cache_pos_ += n;
        if (cache_pos_ >= cache_size_ && !read_next_block()) return false;
    }
    buffer.bytes[i] = '\n';
    ++cache_pos_;
    copied_ = true;
    return true;
}

bool StreamBuffer::read_next_block() {
    const std::uint64_t left = file_pos_ < file_.size() ? file_.size() - file_pos_ : 0;
    const std::size_t n = std::size_t(std::min<std::uint64_t>(cache_size_, left));
    if (n == 0) return false;
    std::memcpy(cache_.data(), file_.bytes(file_pos_, n), n);
    cache_size_ = n;
    file_pos_ += cache_size_;
    cache_pos_ = 0;
    return true;
}

// ---- ParsingUtils' pointer walks, and PLY::DOM's erasing ones over them ----

std::size_t past_spaces(const Buffer& b, std::size_t i) {
    while (is_space(b.at(i))) ++i;
    return i;
}
std::size_t past_line(const Buffer& b, std::size_t i) {  // Assimp::SkipLine
    while (b.at(i) != '\r' && b.at(i) != '\n' && b.at(i) != '\0') ++i;
    while (b.at(i) == '\r' || b.at(i) == '\n') ++i;
    return i;
}
std::size_t token_at(const Buffer& b, std::size_t i, const char* token) {
    const std::size_t n = std::strlen(token);
    for (std::size_t k = 0; k < n; ++k)
        if (b.at(i + k) != token[k]) return 0;
    const char after = b.at(i + n);
    if (!is_space(after) && !is_line_end(after)) return 0;
    return after != '\0' ? n + 1 : n;
}

bool skip_spaces(Buffer& b) {
    if (b.bytes.empty()) return false;
    const std::size_t i = past_spaces(b, 0);
    const bool more = !is_line_end(b.at(i));
    b.bytes.erase(0, i);
    return more;
}
std::size_t skip_line(Buffer& b) {  // how much it erased
    if (b.bytes.empty()) return 0;
    const std::size_t i = past_line(b, 0);
    b.bytes.erase(0, i);
    return i;
}
bool skip_spaces_and_line_end(Buffer& b) {
    if (b.bytes.empty()) return false;
    std::size_t i = 0;
    while (is_space(b.at(i)) || b.at(i) == '\r' || b.at(i) == '\n') ++i;
    const bool more = b.at(i) != '\0';
    b.bytes.erase(0, i);
    return more;
}
bool token_match(Buffer& b, const char* token) {
    if (b.bytes.empty()) return false;
    const std::size_t n = token_at(b, 0, token);
    b.bytes.erase(0, n);
    return n > 0;
}
// PLY::DOM::SkipComments, which walks a copy and keeps it only for a
// comment that does not name a TextureFile. Returns how much it erased.
std::size_t skip_comments(Buffer& b) {
    if (b.bytes.empty()) return 0;
    std::size_t i = past_spaces(b, 0);
    if (is_line_end(b.at(i))) return 0;
    const std::size_t comment = token_at(b, i, "comment");
    if (comment == 0) return 0;
    i = past_spaces(b, i + comment);
    if (is_line_end(b.at(i))) i = past_line(b, i);
    if (token_at(b, i, "TextureFile") > 0) return 0;
    i = past_line(b, i);
    b.bytes.erase(0, i);
    return i;
}

// ---- fast_atof.h: where a value ends ----

bool parse_value(const Buffer& b, std::size_t& i, Type type, std::uint64_t& length) {
    if (type == Type::uint8 || type == Type::uint16 || type == Type::uint32) {
        length = strtoul10(b.bytes, i);
        return true;
    }
    if (type == Type::int8 || type == Type::int16 || type == Type::int32) {
        const bool negative = b.at(i) == '-';
        if (negative || b.at(i) == '+') ++i;
        const std::uint32_t v = strtoul10(b.bytes, i);
        length = negative ? std::uint32_t(0u - v) : v;  // strtol10's int, as unsigned
        return true;
    }
    // fast_atoreal_move (with check_comma): the value only as a length --
    // whole numbers below 2^24 exactly, anything else as "too long".
    length = 0xffffffffu;
    const bool negative = b.at(i) == '-';
    if (negative || b.at(i) == '+') ++i;
    auto named = [&](const char* word) {
        for (std::size_t k = 0; word[k]; ++k)
            if (std::tolower(static_cast<unsigned char>(b.at(i + k))) != word[k]) return false;
        return true;
    };
    if (named("nan")) return i += 3, true;
    if (named("inf")) return i += named("infinity") ? 8 : 3, true;
    auto digit = [&](std::size_t k) { return b.at(k) >= '0' && b.at(k) <= '9'; };
    const bool point = b.at(i) == '.' || b.at(i) == ',';
    if (!digit(i) && !(point && digit(i + 1))) return false;
    bool whole = true;
    std::uint64_t v = 0;
    if (!point) {  // strtoul10_64: on overflow it returns 0 and leaves the pointer where it was
        bool overflow = false;
        std::size_t k = i;
        for (; digit(k); ++k) {
            const std::uint64_t next = v * 10 + std::uint64_t(b.at(k) - '0');
            if (next < v) overflow = true;
            v = next;
        }
        if (overflow) return length = 0, true;
        i = k;
    }
    if ((b.at(i) == '.' || b.at(i) == ',') && digit(i + 1)) {
        for (++i; digit(i); ++i)
            if (b.at(i) != '0') whole = false;
    } else if (b.at(i) == '.') {
        ++i;
    }
    if (b.at(i) == 'e' || b.at(i) == 'E') {
        ++i;
        if (b.at(i) == '-' || b.at(i) == '+') ++i;
        if (!digit(i)) return false;  // strtoul10_64 throws
        while (digit(i)) ++i;
        whole = false;
    }
    if (whole && !negative && v < (std::uint64_t(1) << 24)) length = v;
    return true;
}

}  // namespace fh::assimp_replay
