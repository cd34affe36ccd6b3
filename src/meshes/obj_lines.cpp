#include "meshes/obj_lines.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>

#include "meshes/assimp_replay.h"
#include "text/input_error.h"

namespace fh {

namespace {

using assimp_replay::is_line_end;
using assimp_replay::is_space;
using assimp_replay::is_space_or_line_end;

// IOStreamBuffer's cache: the file is read in blocks of this size.
constexpr std::uint64_t kCache = std::uint64_t(1) << 24;
constexpr std::uint64_t kNoSkip = ~std::uint64_t(0);

// What getFace makes of a line statement, besides a count of vertices.
enum : int { kAssimpRefuses = -1, kPastTheLine = -2 };

// The vertices getFace reads for the line statement `line` (its keyword
// first), or one of the above.
int line_vertices(const std::string& line, bool texture_coordinates, bool normals) {
    std::size_t i = 0;
    // getNextToken: past the keyword, then past spaces (not line ends).
    while (i < line.size() && !is_space_or_line_end(line[i])) ++i;
    while (i < line.size() && is_space(line[i])) ++i;
    int position = 0, vertices = 0;
    while (i < line.size()) {
        const char c = line[i];
        std::size_t step = 1;
        if (is_line_end(c)) break;
        if (c == '/') {
            ++position;
        } else if (is_space_or_line_end(c)) {
            position = 0;
        } else {
            const int value = int(std::strtol(line.c_str() + i, nullptr, 10));  // atoi
            if (value < 0) ++step;
            for (int digits = value; (digits /= 10) != 0;) ++step;
            if (position == 1 && !texture_coordinates && normals) position = 2;
            if (value == 0) return kAssimpRefuses;  // "OBJ: Invalid face index."
            // reportErrorTokenInFace skips to the next line end, past this
            // line's, into what assimp's buffer holds from earlier lines.
            if (position > 2) return kPastTheLine;
            if (position == 0) ++vertices;
        }
        i += step;
    }
    return vertices;
}

// The statements whose text the check keeps: vertices (their colours),
// and the face, line and point statements getFace reads.
bool kept(char first) { return first == 'v' || first == 'f' || first == 'l' || first == 'p'; }

// The words of a statement, separated by spaces and tabs.
int words(const std::string& statement) {
    int n = 0;
    bool in_word = false;
    for (const char c : statement) {
        const bool blank = c == ' ' || c == '\t';
        n += !blank && !in_word;
        in_word = !blank;
    }
    return n;
}

}  // namespace

bool check_obj_lines(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;  // the loader says why
    // The statement being read: its first two characters and its length,
    // and all of it for a line or vertex statement; the physical line it
    // starts on. How many vertex statements, and how many with a colour.
    std::string line;
    char first = '\0', second = '\0';
    std::size_t length = 0;
    int number = 1, starts = 1;
    bool texture_coordinates = false, normals = false;
    std::size_t vertex_statements = 0, colored_vertices = 0;
    bool vertical_tab = false;  // in the statement
    auto take = [&](char c) {
        if (length == 0) first = c;
        if (length == 1) second = c;
        ++length;
        if (kept(first)) line += c;
        vertical_tab |= c == '\v';
    };
    auto untake = [&] {  // the last character taken
        --length;
        if (kept(first)) line.pop_back();
        if (length == 0) first = '\0';
        if (length == 1) second = '\0';
    };
    auto statement_ends = [&] {
        if (first == 'v' && length >= 2) {
            texture_coordinates |= second == 't';
            normals |= second == 'n';
            if (second == ' ' || second == '\t') {
                ++vertex_statements;
                colored_vertices += words(line) == 7;  // "v" and six numbers
            }
        }
        // getFace reads each index by atoi, which skips a vertical tab and
        // then the line's end, and reads on past the end of assimp's line
        // buffer when the statement fills it (a file of one line).
        const bool face = first == 'f' || first == 'l' || first == 'p';  // getFace reads all three
        if (face && vertical_tab)
            throw InputError(path, starts, 1,
                             "a vertical tab (byte 0x0b) in a face statement, which assimp 5.2.5 reads past "
                             "(its atoi skips it and the line's end)");
        if (face) {
            const int n = line_vertices(line, texture_coordinates, normals);
            const std::string kind = first == 'f' ? "face" : first == 'l' ? "line" : "point";
            const std::string unused = first == 'f' ? "" : first == 'l' ? " (firsthit draws no lines)"
                                                                         : " (firsthit draws no points)";
            if (first == 'l' && n == 1)
                throw InputError(path, starts, 1,
                                 "a line statement of one vertex, for which assimp 5.2.5 writes past the end of its "
                                 "vertex array" + unused);
            if (n == kPastTheLine)
                throw InputError(path, starts, 1,
                                 "a " + kind + " statement with a vertex of more than three indices, which assimp "
                                 "5.2.5 reads on past its line" + unused);
        }
        line.clear();
        first = second = '\0';
        length = 0;
        vertical_tab = false;
    };
    // getNextDataLine: "\" before a line end drops both, skips to the next
    // '\n' and takes the character after it unexamined.
    enum { kReading, kSkipping, kTaking } state = kReading;
    bool backslash = false;  // the last character read (and examined) was "\"
    // Its cache of 16 MiB: a "\" on a block's last byte makes it look at the
    // byte after the cache, and one before a line end other than '\n' makes
    // it look for the next '\n' -- past the cache where none follows in the
    // block. Raw bytes are enough: the file's blocks are the cache's.
    // (The file's last byte too: what follows it there is left from the
    // block before.)
    in.seekg(0, std::ios::end);
    const std::uint64_t size = std::uint64_t(std::max<std::streamoff>(in.tellg(), 0));
    const bool over_a_block = size > kCache;
    in.seekg(0);
    std::uint64_t offset = 0;
    std::uint64_t skip_block = kNoSkip;  // the block a "\" + line end was seen in, until its '\n'
    auto past_the_cache = [&] {
        throw InputError(path, number, 1,
                         "a '\\' before a line end that makes assimp 5.2.5 read past the end of its 16 MiB "
                         "line cache");
    };
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        const std::streamsize n = in.gcount();
        for (std::streamsize k = 0; k < n; ++k, ++offset) {
            const char c = chunk[k];
            if (over_a_block) {
                const std::uint64_t block = offset / kCache;
                if (c == '\n' && skip_block != kNoSkip) {
                    if (skip_block != block) past_the_cache();
                    skip_block = kNoSkip;
                }
                const char next = k + 1 < n ? chunk[k + 1] : char(in.peek());
                if (c == '\\' && (offset % kCache == kCache - 1 || offset + 1 == size)) past_the_cache();
                if (c == '\\' && (next == '\r' || next == '\0' || next == '\f') && skip_block == kNoSkip)
                    skip_block = (offset + 1) / kCache;
            }
            if (c == '\n') ++number;
            if (state == kSkipping) {
                if (c == '\n') state = kTaking;
                continue;
            }
            if (state == kTaking) {
                take(c);
                state = kReading;
                backslash = false;
                continue;
            }
            if (backslash && is_line_end(c)) {  // the "\" was taken: untake it
                untake();
                state = c == '\n' ? kTaking : kSkipping;
                backslash = false;
                continue;
            }
            backslash = c == '\\';
            if (is_line_end(c)) {
                statement_ends();
                starts = number;
                continue;
            }
            take(c);
        }
    }
    if (skip_block != kNoSkip) past_the_cache();
    if (length > 0) statement_ends();
    return vertex_statements > 0 && colored_vertices == vertex_statements;
}

}  // namespace fh
