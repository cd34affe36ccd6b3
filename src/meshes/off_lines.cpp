#include "meshes/off_lines.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>

#include "meshes/assimp_replay.h"
#include "meshes/mesh_text.h"
#include "text/input_error.h"

namespace fh {

namespace {

using assimp_replay::is_line_end;
using assimp_replay::strtoul10;
using mesh_text::plural;
using mesh_text::saturating_add;
using mesh_text::saturating_mul;

// ParsingUtils' GetNextLine copies a line into char[BufferSize] and ends it
// with a zero at the copy's end: at out[4096] for a line this long.
constexpr std::size_t kLineBuffer = 4096;

}  // namespace

void check_off_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string t((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (t.size() < 8) return;  // assimp's to refuse ("File is too small")
    switch (assimp_replay::byte_order_mark(t, t.size())) {
    case assimp_replay::ByteOrderMark::utf32:
        throw InputError(path, assimp_replay::kUtf32Refused);
    case assimp_replay::ByteOrderMark::utf8: t.erase(0, 3); break;
    case assimp_replay::ByteOrderMark::none: break;
    }
    t.push_back('\0');  // TextFileToBuffer ends the text with a zero
    const std::size_t end = t.size();

    // The header: NextToken skips blanks, line ends and lines that start
    // with '#' (SkipSpacesAndLineEnd, then SkipLine).
    std::size_t at = 0;
    auto skip_blanks = [&] {
        while (t[at] == ' ' || t[at] == '\t' || t[at] == '\r' || t[at] == '\n') ++at;
    };
    auto next_token = [&] {
        skip_blanks();
        while (at < end && (t[at] == '#' || t[at] == '\n' || t[at] == '\r')) {
            while (t[at] != '\r' && t[at] != '\n' && t[at] != '\0') ++at;
            while (t[at] == '\r' || t[at] == '\n') ++at;
            skip_blanks();
        }
    };
    auto starts = [&](const char* word, std::size_t n) { return at + n < end && t.compare(at, n, word) == 0; };
    next_token();
    if (starts("ST", 2)) at += 2;
    if (starts("C", 1)) ++at;
    if (starts("N", 1)) ++at;
    if (starts("4", 1)) ++at;
    const bool has_dimension = starts("n", 1);
    if (has_dimension) ++at;
    if (starts("OFF", 3)) {
        at += 3;
        next_token();
    } else {
        next_token();
        if (at + 1 >= end || t[at] < '0' || t[at] > '9') return;  // assimp's to refuse
    }
    std::uint32_t dimensions = 3;
    if (has_dimension) {
        dimensions = strtoul10(t, at);
        next_token();
    }
    if (dimensions > 3) return;  // assimp's to refuse
    next_token();
    const std::uint32_t vertices = strtoul10(t, at);
    next_token();
    const std::uint32_t faces = strtoul10(t, at);
    const std::size_t after_counts = at;
    next_token();
    strtoul10(t, at);  // the edges
    next_token();
    if (vertices == 0 || faces == 0) return;  // assimp's to refuse ("no valid vertices/faces")

    // A vertex takes at least two bytes a coordinate ("0 "), a face two.
    const std::uint64_t rest = end - 1 - after_counts;
    std::uint64_t needed = saturating_add(saturating_mul(vertices, 2 * std::max<std::uint64_t>(dimensions, 1)),
                                          saturating_mul(faces, 2));
    if (needed > 0) --needed;  // the last line's newline may be missing
    if (needed > rest)
        throw InputError(path, "the OFF header declares " + plural(vertices, "vertex", "vertices") + " and " +
                                   plural(faces, "face", "faces") + " (at least " + plural(needed, "byte", "bytes") +
                                   ") but only " + plural(rest, "byte follows", "bytes follow") +
                                   " the counts: a truncated file?");

    // The lines, as GetNextLine gives them: up to a line end (or a zero,
    // which ends the text), then past the line ends.
    int line = 1 + int(std::count(t.begin(), t.begin() + std::ptrdiff_t(at), '\n'));
    std::size_t first = at;
    auto next_line = [&] {
        if (t[at] == '\0') return false;
        first = at;
        while (!is_line_end(t[at]) && at - first < kLineBuffer) ++at;
        if (at - first == kLineBuffer)
            throw InputError(path, line, 1,
                             "a line of 4,096 bytes or more: assimp 5.2.5's OFF reader copies each line into "
                             "4,096 bytes and would end the copy past them");
        return true;
    };
    auto past_line_ends = [&] {
        for (; is_line_end(t[at]) && t[at] != '\0'; ++at) line += t[at] == '\n';
    };
    for (std::uint32_t v = 0; v < vertices && next_line(); ++v) past_line_ends();
    for (std::uint32_t f = 0; f < faces && next_line();) {
        std::size_t i = first;
        while (t[i] == ' ' || t[i] == '\t') ++i;
        const std::uint32_t count = strtoul10(t, i);
        // assimp counts its faces down for such a line, past 0 when there
        // are more of them than faces: the validator then reads past the
        // face array.
        if (count == 0 || count > 9)
            throw InputError(path, line, 1, "a face with no vertices, or with more than 9 (the most assimp's OFF "
                                            "reader takes)");
        ++f;
        past_line_ends();
    }
}

}  // namespace fh
