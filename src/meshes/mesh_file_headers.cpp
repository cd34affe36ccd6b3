#include "meshes/mesh_file_headers.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

#include "text/input_error.h"
#include "meshes/assimp_replay.h"
#include "meshes/mesh_text.h"

namespace fh {

namespace {

using mesh_text::lowercase;
using mesh_text::plural;
using mesh_text::saturating_add;
using mesh_text::saturating_mul;
using mesh_text::starts_with;

// At most the first `max_bytes` of the file.
std::string read_head(const std::string& path, std::size_t max_bytes) {
    std::ifstream in(path, std::ios::binary);
    std::string head(max_bytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(max_bytes));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

// Bytes of one binary PLY value of `type` (1 for a name assimp will reject).
std::uint64_t ply_type_bytes(const std::string& type) {
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 1;
}

}  // namespace


// The PLY header's element counts against the bytes after it. Leaves files
// that do not start with "ply" to assimp, which says so.
PlyHeader check_ply_header(const std::string& path, std::uintmax_t file_size) {
    constexpr std::size_t kMaxHeader = std::size_t(1) << 20;
    const std::string head = read_head(path, kMaxHeader);
    if (lowercase(head.substr(0, 3)) != "ply") return {};
    std::size_t end = std::string::npos;
    for (std::size_t at = head.find("end_header"); at != std::string::npos; at = head.find("end_header", at + 1)) {
        const std::size_t after = at + 10;
        if ((at == 0 || head[at - 1] == '\n') &&
            (after == head.size() || std::isspace(static_cast<unsigned char>(head[after])))) {
            end = at;
            break;
        }
    }
    if (end == std::string::npos && head.size() == kMaxHeader && file_size > kMaxHeader)
        throw InputError(path, "the PLY header has no end_header line in its first 1 MiB (firsthit reads headers up "
                               "to 1 MiB)");
    if (end == std::string::npos)
        throw InputError(path, "the PLY header has no end_header line (a truncated file?)");
    const std::size_t newline = head.find('\n', end);
    // assimp 5.2.5 reads past the end for ever when the file ends on
    // end_header after a line it does not know (fuzzing found two): a PLY's
    // header ends with a line end, and data, if any, follows it.
    if (newline == std::string::npos && head.size() == file_size)
        throw InputError(path, "the PLY header's end_header line has no line end (a truncated file?)");
    const std::uintmax_t data_start = newline == std::string::npos ? file_size : newline + 1;
    const std::uint64_t data_bytes = file_size - std::min<std::uintmax_t>(data_start, file_size);

    struct Element {
        std::string name;
        std::uint64_t count = 0;
        std::uint64_t bytes = 0;  // at least, per instance
    };
    std::vector<Element> elements;
    bool binary = false;
    int color_channels = 0;  // the vertex element's red, green and blue of a type drawn (PlyHeader)
    std::istringstream lines(head.substr(0, end));
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string word, name, count;
        words >> word;
        if (word == "format") {
            words >> name;
            binary = starts_with(name, "binary");
        } else if (word == "element") {
            words >> name >> count;
            // Read as assimp will, garbled or not: fuzzing found a
            // 4-billion-vertex header hidden behind a garbled count, and one
            // whose count ran into the next line's word
            // ("42949672954\bproperty", 4,294,967,290 to assimp).
            std::size_t digits = 0;
            Element e{name, assimp_replay::strtoul10(count, digits), 0};
            elements.push_back(e);
        } else if (word == "property" && !elements.empty()) {
            words >> name;  // the type; for a list, the type of its length
            if (name == "list") words >> name;
            std::string property;
            words >> property;
            const bool drawn_type = name == "uchar" || name == "uint8" || name == "float" || name == "float32" ||
                                    name == "double" || name == "float64";
            if (elements.back().name == "vertex" && drawn_type &&
                (property == "red" || property == "green" || property == "blue"))
                ++color_channels;
            // ASCII: a value and a separator.
            elements.back().bytes += binary ? ply_type_bytes(name) : 2;
        }
    }
    std::uint64_t needed = 0;
    std::string declared;
    for (const Element& e : elements) {
        needed = saturating_add(needed, saturating_mul(e.count, std::max<std::uint64_t>(e.bytes, 1)));
        declared += (declared.empty() ? "element " : ", element ") + e.name + " " + std::to_string(e.count);
    }
    if (!binary && needed > 0) --needed;  // the last line's newline may be missing
    if (needed > data_bytes)
        throw InputError(path, "the PLY header declares " + declared + " (at least " + plural(needed, "byte", "bytes") +
                                   " of data) but only " + plural(data_bytes, "byte follows", "bytes follow") +
                                   " it: a truncated file?");
    const bool crlf = newline != std::string::npos && newline > 0 && head[newline - 1] == '\r';
    if (binary && !crlf && newline != std::string::npos && newline + 1 < head.size() && head[newline + 1] == '\n')
        throw InputError(path,
                         "binary PLY data starting with byte 0x0a: assimp takes it for the header's line end and "
                         "misreads everything after it (assimp issue #5341)");
    return {binary, color_channels == 3};
}

// An STL file goes through TextFileToBuffer, binary or not.
void check_stl_start(const std::string& path, std::uintmax_t file_size) {
    if (assimp_replay::byte_order_mark(read_head(path, 4), file_size) == assimp_replay::ByteOrderMark::utf32)
        throw InputError(path, assimp_replay::kUtf32Refused);
}

}  // namespace fh
