// Debian's assimp 5.2.5 reading a PLY file, replayed: its line buffer
// (IOStreamBuffer, with PlyLoader's 1 MiB cache, and the bytes its buffer
// keeps from earlier lines), the pointer walks of its parser (ParsingUtils,
// PLY::DOM) and where each value it reads ends (fast_atof). Only what
// decides where assimp reads, not the values: meshes/ply_lists.cpp uses it
// to find the list lengths assimp will size lists by (and meshes/obj_lines.cpp
// and meshes/off_lines.cpp its ParsingUtils character tests; the OFF and STL
// checks its byte order marks). Each function is named after the one it
// follows.
#pragma once

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>

namespace fh::assimp_replay {

// A place where assimp would read outside its buffer: nothing can be said
// of what it does then, so the file is refused.
struct PastTheBuffer {};

// assimp's std::vector<char> buffer, read with assimp's pointer walks.
struct Buffer {
    std::string bytes;
    char at(std::size_t i) const {
        if (i >= bytes.size()) throw PastTheBuffer{};
        return bytes[i];
    }
};

// strtoul10: the digits from text[at] on (`at` moves past them), in 32 bits
// that wrap, whatever follows them; 0 without any. Stops at the text's end.
inline std::uint32_t strtoul10(const std::string& text, std::size_t& at) {
    std::uint32_t value = 0;
    for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at)
        value = value * 10 + std::uint32_t(text[at] - '0');
    return value;
}

// BaseImporter::ConvertToUTF8, which TextFileToBuffer runs over an OFF or
// STL file of 8 bytes or more: a UTF-8 byte order mark (EF BB BF) is
// dropped; what it takes for a UTF-32 one (FE FF 00 00) it converts by
// reading 4 bytes past the file's end (fixed in 6.0) -- refused, with
// kUtf32Refused. Its other marks change nothing it then reads.
enum class ByteOrderMark { none, utf8, utf32 };
inline ByteOrderMark byte_order_mark(const std::string& file_start, std::uint64_t file_size) {
    auto is = [&](const char* bytes, std::size_t n) { return file_start.compare(0, n, bytes, n) == 0; };
    if (file_size < 8) return ByteOrderMark::none;  // "File is too small"
    if (is("\xEF\xBB\xBF", 3)) return ByteOrderMark::utf8;
    if (is("\xFE\xFF\0\0", 4)) return ByteOrderMark::utf32;
    return ByteOrderMark::none;
}
inline constexpr const char* kUtf32Refused =
    "the file starts with bytes FE FF 00 00, which assimp 5.2.5 takes for a UTF-32 byte order mark: converting "
    "the text, it would read past the file's end";

inline bool is_line_end(char c) { return c == '\r' || c == '\n' || c == '\0' || c == '\f'; }
inline bool is_space(char c) { return c == ' ' || c == '\t'; }
inline bool is_space_or_line_end(char c) { return is_space(c) || is_line_end(c); }

// The bytes at [at, at + n) of a file, n at most a block, through one block
// kept in memory: the check reads as assimp does, front to back, without
// holding the whole file.
class FileBlocks {
public:
    FileBlocks(std::ifstream& in, std::uint64_t size)
        : in_(in), size_(size), block_(std::size_t(std::min<std::uint64_t>(size, std::uint64_t(1) << 20)), '\0') {}

    std::uint64_t size() const { return size_; }
    // The block holding [at, at + n) (which must lie inside the file), and where `at` is in it.
    const char* bytes(std::uint64_t at, std::size_t n) {
        if (at < first_ || at + n > first_ + filled_) {
            in_.clear();
            in_.seekg(std::streamoff(at));
            in_.read(block_.data(), std::streamsize(block_.size()));
            first_ = at;
            filled_ = std::size_t(std::max<std::streamsize>(in_.gcount(), 0));
            if (at + n > first_ + filled_) throw PastTheBuffer{};  // the file shrank meanwhile
        }
        return block_.data() + (at - first_);
    }

private:
    std::ifstream& in_;
    std::uint64_t size_;
    std::string block_;
    std::uint64_t first_ = 0;
    std::size_t filled_ = 0;
};

// Bytes that end a line for assimp (IsLineEnd), as a table.
struct LineEnds {
    bool at[256] = {};
    constexpr LineEnds() { at[size_t('\r')] = at[size_t('\n')] = at[size_t('\0')] = at[size_t('\f')] = true; }
};
inline constexpr LineEnds kLineEnds;

// IOStreamBuffer<char> with PlyLoader's 1 MiB cache: the lines assimp
// reads, with what its buffer keeps between them.
class StreamBuffer {
public:
    explicit StreamBuffer(FileBlocks& file)
        : file_(file),
          cache_(std::size_t(1) << 20, '\n'),
          cache_size_(std::size_t(std::min<std::uint64_t>(cache_.size(), file.size()))) {}

    // getNextLine: the next line into `buffer`, as assimp leaves it; false
    // at the end (the buffer may still have been written: copied()).
    bool get_next_line(Buffer& buffer);

    // Where binary data starts (getNextBlock after the header's last line).
    std::uint64_t file_position() const { return file_pos_ - cache_size_ + cache_pos_; }
    // getNextBlock would hand over an empty buffer: the last line read ended
    // on the cache's last byte (a full 1 MiB block).
    bool next_block_empty() const { return cache_pos_ == cache_.size(); }
    int lines() const { return lines_; }  // read so far (the last one's number)
    bool copied() const { return copied_; }  // the last get_next_line wrote into the buffer
    std::size_t line_length() const { return length_; }  // the bytes it copied, before its '\n'

private:
    char cache(std::size_t i) const {
        if (i >= cache_.size()) throw PastTheBuffer{};
        return cache_[i];
    }
    bool read_next_block();

    FileBlocks& file_;
    std::string cache_;
    std::size_t cache_size_, cache_pos_ = 0;
    std::uint64_t file_pos_ = 0;
    int lines_ = 0;
    bool copied_ = false;
    std::size_t length_ = 0;
};

// Where assimp's pointer walks stop, from b[i] on: past spaces and tabs
// (SkipSpaces), past the line and its line ends (SkipLine), and past a
// token and the space or line end after it (TokenMatch; 0: no match).
std::size_t past_spaces(const Buffer& b, std::size_t i);
std::size_t past_line(const Buffer& b, std::size_t i);
std::size_t token_at(const Buffer& b, std::size_t i, const char* token);

// PLY::DOM's helpers: each walks from the buffer's start and erases what it
// passed. skip_line and skip_comments return how much they erased.
bool skip_spaces(Buffer& b);
std::size_t skip_line(Buffer& b);
bool skip_spaces_and_line_end(Buffer& b);
bool token_match(Buffer& b, const char* token);
std::size_t skip_comments(Buffer& b);  // a comment line, unless it names a TextureFile

// PLY's value types (PLY::EDataType).
enum class Type { invalid, int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline std::size_t bytes_of(Type t) {
    switch (t) {
    case Type::int8: case Type::uint8: return 1;
    case Type::int16: case Type::uint16: return 2;
    case Type::int32: case Type::uint32: case Type::float32: return 4;
    case Type::float64: return 8;
    default: return 0;
    }
}

// Where assimp stops reading a value of `type` at b[i] (PropertyInstance::
// ParseValue; i moves there), and the value as a list length (ConvertTo<
// unsigned int>; float values only as whole numbers below 2^24, anything
// else as 0xffffffff); false where assimp throws (fast_atoreal_move on a
// value that is no number).
bool parse_value(const Buffer& b, std::size_t& i, Type type, std::uint64_t& length);

}  // namespace fh::assimp_replay
