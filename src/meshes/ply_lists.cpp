#include "meshes/ply_lists.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "meshes/assimp_replay.h"
#include "text/input_error.h"

// The header read as PLY::DOM::ParseHeader reads it, then the data as
// ParseElementInstanceLists(Binary) does (code/AssetLib/Ply/PlyParser.cpp of
// assimp 5.2.5), each function named after the one it follows, over the
// replayed line buffer and pointer walks (meshes/assimp_replay.h).
namespace fh {

namespace {

using namespace assimp_replay;

Type parse_data_type(Buffer& b) {
    const std::pair<const char*, Type> names[] = {
        {"char", Type::int8},     {"int8", Type::int8},       {"uchar", Type::uint8},   {"uint8", Type::uint8},
        {"short", Type::int16},   {"int16", Type::int16},     {"ushort", Type::uint16}, {"uint16", Type::uint16},
        {"int32", Type::int32},   {"int", Type::int32},       {"uint32", Type::uint32}, {"uint", Type::uint32},
        {"float", Type::float32}, {"float32", Type::float32}, {"double64", Type::float64},
        {"double", Type::float64}, {"float64", Type::float64}};
    for (const auto& [name, type] : names)
        if (token_match(b, name)) return type;
    return Type::invalid;
}

struct Property {
    bool list = false;
    Type length = Type::invalid, value = Type::invalid;
    const char* name = "";  // the name, where assimp knows it
};

struct Element {
    bool parsed_in_ascii = false;  // a semantic assimp knows (vertex, face, ...): its lines are parsed
    const char* name = "";         // the name, where assimp knows it
    std::uint32_t count = 0;
    std::vector<Property> properties;

    bool has_list() const {
        return std::any_of(properties.begin(), properties.end(), [](const Property& p) { return p.list; });
    }
};

bool parse_property(Buffer& b, Property& p) {
    if (!skip_spaces(b) || !token_match(b, "property") || !skip_spaces(b)) return false;
    if (token_match(b, "list")) {
        p.list = true;
        if ((p.length = parse_data_type(b)) == Type::invalid) return skip_line(b), false;
        if (!skip_spaces(b)) return false;
    }
    if ((p.value = parse_data_type(b)) == Type::invalid) return skip_line(b), false;
    if (!skip_spaces(b)) return false;
    // The name's semantic: a name assimp does not know has the line skipped.
    const char* known[] = {"red", "green", "blue", "alpha", "vertex_index", "vertex_indices", "texcoord",
                           "material_index", "ambient_red", "ambient_green", "ambient_blue", "ambient_alpha",
                           "diffuse_red", "diffuse_green", "diffuse_blue", "diffuse_alpha", "specular_red",
                           "specular_green", "specular_blue", "specular_alpha", "opacity", "specular_power", "r",
                           "g", "b", "u", "s", "tx", "texture_u", "v", "t", "ty", "texture_v", "x", "y", "z",
                           "nx", "ny", "nz"};
    for (const char* name : known)
        if (!*p.name && token_match(b, name)) p.name = name;
    if (!*p.name) skip_line(b);
    skip_spaces_and_line_end(b);
    return true;
}

bool parse_element(StreamBuffer& stream, Buffer& b, Element& e) {
    if (!skip_spaces(b)) return false;
    if (!token_match(b, "element") && !token_match(b, "comment")) return false;
    if (!skip_spaces(b)) return false;
    bool known = false, texture_file = false;
    for (const char* name : {"vertex", "face", "tristrips", "edge", "material"})
        if (!known && token_match(b, name)) known = true, e.name = name;
    if (!known && token_match(b, "TextureFile")) texture_file = true;
    if (!known)  // assimp keeps the name up to the buffer's zero (strlen)
        for (std::size_t i = 0; b.at(i) != '\0';) ++i;
    if (!skip_spaces(b)) return false;
    if (texture_file) return skip_spaces_and_line_end(b), true;
    // strtoul10 -- from the name itself when assimp did not know it.
    std::size_t digits = 0;
    e.count = strtoul10(b.bytes, digits);
    e.parsed_in_ascii = known;
    skip_spaces_and_line_end(b);
    for (;;) {
        if (!stream.get_next_line(b)) throw PastTheBuffer{};  // assimp would read this line for ever
        skip_comments(b);
        Property p;
        if (!parse_property(b, p)) break;
        e.properties.push_back(p);
    }
    return true;
}

// At least a byte an element (a line end, or a value), or assimp loops on:
// a count assimp read from a name it did not know ("element 4000000000 1"),
// or an element without properties.
void check_count(const Element& e, std::uint64_t file_size, const std::string& path) {
    if (e.count > file_size)
        throw InputError(path, "assimp 5.2.5 would read " + std::to_string(e.count) +
                                   " instances of a PLY element from a file of " + std::to_string(file_size) +
                                   " bytes");
}

// The elements PLYImporter fills its mesh from, as it does (LoadVertex,
// LoadFace): the first vertex element sizes the vertex arrays and every
// vertex element writes into them, each from its own index 0 -- a second,
// longer one writes past their end (heap corruption: a 300-byte file aborts
// the process in glibc's malloc) -- and so the first face or tristrips
// element the face array. (An element of no instances writes nothing.) A
// face element's texture coordinates are read through its vertex indices,
// a null pointer when it has none (a crash). Refused, all three; the
// assimp-testmodels PLY files have none of them.
void check_elements(const std::vector<Element>& elements, const std::string& path) {
    using Names = std::initializer_list<std::string_view>;
    auto one_of = [](const char* name, Names names) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    auto elements_named = [&](Names names) {
        return std::count_if(elements.begin(), elements.end(),
                             [&](const Element& e) { return e.count > 0 && one_of(e.name, names); });
    };
    const std::string why = " (assimp 5.2.5 would write past the end of its arrays)";
    if (elements_named({"vertex"}) > 1) throw InputError(path, "a PLY header with two 'vertex' elements" + why);
    if (elements_named({"face", "tristrips"}) > 1)
        throw InputError(path, "a PLY header with two elements of faces ('face' or 'tristrips')" + why);
    for (const Element& e : elements) {
        auto has_list = [&](Names names) {
            return std::any_of(e.properties.begin(), e.properties.end(),
                               [&](const Property& p) { return p.list && one_of(p.name, names); });
        };
        if (one_of(e.name, {"face"}) && has_list({"texcoord"}) && !has_list({"vertex_index", "vertex_indices"}))
            throw InputError(path, "a PLY 'face' element with texture coordinates but no vertex indices (assimp "
                                   "5.2.5 would read them through a null pointer)");
    }
}

// A face's texture coordinates (LoadFace): for a list of 6, 7 or 8 values
// assimp reads the vertex index of each two, the fourth for the seventh
// and eighth, whatever the face's own count (still so in 6.0): past the
// indices of a triangle. The properties' indices of the face element's
// (last) vertex index and texture coordinate lists, where it has both.
struct FaceLists {
    int indices = -1, texcoords = -1;
};

FaceLists face_lists(const Element& e) {
    FaceLists f;
    if (std::string_view(e.name) != "face") return f;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const std::string_view name = e.properties[k].name;
        if (!e.properties[k].list) continue;
        if (name == "vertex_index" || name == "vertex_indices") f.indices = int(k);
        if (name == "texcoord") f.texcoords = int(k);
    }
    if (f.indices < 0) f.texcoords = -1;  // check_elements refuses these
    return f;
}

// Each property's number of values in one instance: true where assimp
// reads the indices far enough for the coordinates.
bool indices_cover_texcoords(const FaceLists& f, const std::vector<std::uint64_t>& values) {
    if (f.texcoords < 0) return true;
    const std::uint64_t t = values[size_t(f.texcoords)];
    return t / 3 != 2 || values[size_t(f.indices)] > (t - 1) / 2;
}

std::string texcoords_past_indices(const FaceLists& f, const std::vector<std::uint64_t>& values) {
    return "a PLY face with " + std::to_string(values[size_t(f.texcoords)]) + " texture coordinates but " +
           std::to_string(values[size_t(f.indices)]) +
           " vertex indices: assimp 5.2.5 would read past the indices (one for each two coordinates)";
}

// One ASCII line of an element assimp parses (ElementInstance::ParseInstance):
// false where assimp throws and reads no further. `values`, where given,
// gets each property's number of values as assimp keeps them: a list's
// length, one more where the line ends inside it, and 1 for a property
// the line ends before.
bool check_ascii_instance(const Buffer& b, const Element& e, const std::string& path, int line,
                          std::vector<std::uint64_t>* values = nullptr) {
    std::size_t i = 0;
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        while (is_space(b.at(i))) ++i;
        if (values) (*values)[k] = 1;
        if (is_line_end(b.at(i))) continue;  // missing: assimp puts a default in
        std::uint64_t length = 0;
        const int column = int(i) + 1;
        if (!parse_value(b, i, p.list ? p.length : p.value, length)) return false;
        if (p.list) {
            std::size_t room = 0;  // at least a byte a value
            while (room <= length && !is_line_end(b.at(i + room))) ++room;
            if (length > room) {
                while (!is_line_end(b.at(i + room))) ++room;
                throw InputError(path, line, column,
                                 "a PLY list of " + std::to_string(length) + " values, but only " +
                                     std::to_string(room) + " bytes follow on its line (a corrupt file?)");
            }
            // The last property (the faces' usual list): nothing is read after it.
            if (k + 1 == e.properties.size() && !values) return true;
            bool whole = true;
            for (std::uint64_t n = 0; n < length && whole; ++n) {
                while (is_space(b.at(i))) ++i;
                if (is_line_end(b.at(i))) whole = false;  // assimp leaves the list short
                else if (std::uint64_t unused; !parse_value(b, i, p.value, unused)) return false;
            }
            if (values) (*values)[k] = whole ? length : length + 1;  // a default after the short list
            if (!whole || k + 1 == e.properties.size()) continue;
        }
        // SkipSpacesAndLineEnd: past this line's end, the next property
        // would be read from what an earlier line left in the buffer.
        while (is_space(b.at(i)) || b.at(i) == '\r' || b.at(i) == '\n') {
            if (b.at(i) == '\n' && k + 1 < e.properties.size())
                throw InputError(path, line, int(i) + 1,
                                 "a PLY line holds values for only " + std::to_string(k + 1) + " of its " +
                                     std::to_string(e.properties.size()) +
                                     " properties; assimp would read the others from an earlier line");
            ++i;
        }
    }
    return true;
}

// assimp's line buffer is 1 MiB (its size doubles only when a line
// reaches it): a line one byte shorter leaves its '\n' on the buffer's last
// byte, and the parser's walk past that '\n' reads past the buffer.
constexpr std::size_t kFullLine = (std::size_t(1) << 20) - 1;

void check_ascii(StreamBuffer& stream, Buffer& b, const std::vector<Element>& elements, const std::string& path,
                 std::uint64_t file_size) {
    auto next_line = [&] {
        const bool read = stream.get_next_line(b);
        if (stream.line_length() >= kFullLine)
            throw InputError(path, stream.lines(), 1,
                             "a PLY line of " + std::to_string(stream.line_length()) +
                                 " bytes: assimp 5.2.5 would read past its 1 MiB line buffer after it");
        return read;
    };
    next_line();
    for (auto e_at = elements.begin(); e_at != elements.end(); ++e_at) {
        const Element& e = *e_at;
        const bool parsed = e.parsed_in_ascii && !e.properties.empty();
        // Only lists are sized by what is read: the other elements' lines
        // are passed over (reading them changes nothing in the buffer).
        const bool lists = e.has_list();
        const FaceLists face = face_lists(e);
        std::vector<std::uint64_t> values(e.properties.size());
        check_count(e, file_size, path);
        for (std::uint32_t n = 0; n < e.count; ++n) {
            std::size_t erased = 0;
            if (parsed) {
                if (lists && !check_ascii_instance(b, e, path, stream.lines(), face.texcoords >= 0 ? &values : nullptr))
                    return;
                if (!indices_cover_texcoords(face, values))
                    throw InputError(path, stream.lines(), 1, texcoords_past_indices(face, values));
            } else {
                erased = skip_comments(b);
                erased += skip_line(b);
            }
            const std::size_t size = b.bytes.size();
            // Past the end the buffer stays as it is: every instance the
            // header still declares would be read from this line again --
            // a list of n values, n values each time: n^2 from 2n bytes
            // (120 KB took 14 GB).
            if (!next_line() && !stream.copied() && erased == 0 && b.bytes.size() == size) {
                std::uint64_t left = e.count - n - 1;
                for (auto later = e_at + 1; later != elements.end(); ++later) left += later->count;
                if (left > 0)
                    throw InputError(path, "the PLY data ends " + std::to_string(left) +
                                               " element instances before its header says (a truncated file?); "
                                               "assimp 5.2.5 would read its last line again for each");
                break;
            }
        }
    }
}

void check_binary(FileBlocks& file, std::uint64_t at, bool big_endian, const std::vector<Element>& elements,
                  const std::string& path) {
    auto cut_short = [&] {
        throw InputError(path, "the binary PLY data ends before its elements do (a truncated file?)");
    };
    auto read = [&](Type type) -> std::uint64_t {
        const std::size_t n = bytes_of(type);
        if (file.size() - at < n) cut_short();
        const char* bytes = file.bytes(at, n);
        unsigned char raw[8];
        for (std::size_t k = 0; k < n; ++k) raw[k] = static_cast<unsigned char>(bytes[big_endian ? n - 1 - k : k]);
        at += n;
        std::uint64_t bits = 0;
        std::memcpy(&bits, raw, n);
        switch (type) {
        case Type::int8: return std::uint32_t(std::int32_t(std::int8_t(bits)));
        case Type::int16: return std::uint32_t(std::int32_t(std::int16_t(bits)));
        case Type::float32: case Type::float64: {
            double v;
            if (type == Type::float32) {
                float f;
                std::memcpy(&f, raw, 4);
                v = f;
            } else {
                std::memcpy(&v, raw, 8);
            }
            return v >= 0 && v < 4294967296.0 ? std::uint64_t(v) : 0xffffffffu;
        }
        default: return bits;  // unsigned, and int32 as its 32 bits
        }
    };
    for (const Element& e : elements) {
        check_count(e, file.size(), path);
        if (!e.has_list()) {  // a fixed size: skipped at once
            std::size_t bytes = 0;
            for (const Property& p : e.properties) bytes += bytes_of(p.value);
            if ((file.size() - at) / std::max<std::size_t>(bytes, 1) < e.count && bytes > 0) cut_short();
            at += std::uint64_t(bytes) * e.count;
            continue;
        }
        const FaceLists face = face_lists(e);
        std::vector<std::uint64_t> values(e.properties.size(), 1);
        for (std::uint32_t n = 0; n < e.count; ++n) {
            const std::uint64_t starts = at;
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const Property& p = e.properties[k];
                if (!p.list) {
                    read(p.value);
                    continue;
                }
                const std::uint64_t length = read(p.length);
                if (length > (file.size() - at) / bytes_of(p.value))
                    throw InputError(path, "a binary PLY list of " + std::to_string(length) + " values at byte " +
                                               std::to_string(at) + ", but only " +
                                               std::to_string(file.size() - at) +
                                               " bytes follow (a corrupt or truncated file?)");
                at += length * bytes_of(p.value);
                values[k] = length;
            }
            if (!indices_cover_texcoords(face, values))
                throw InputError(path, texcoords_past_indices(face, values) + " (the face at byte " +
                                           std::to_string(starts) + ")");
        }
    }
}

}  // namespace

void check_ply_lists(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in.tellg();
    if (!in || size <= 0) return;  // the loader says why
    FileBlocks file(in, std::uint64_t(size));
    try {
        StreamBuffer stream(file);
        Buffer magic, format;
        // PLYImporter::InternReadFile: "ply", then the format line; anything
        // else is assimp's to refuse.
        if (!stream.get_next_line(magic) || magic.bytes.size() < 3 ||
            std::tolower(static_cast<unsigned char>(magic.bytes[0])) != 'p' ||
            std::tolower(static_cast<unsigned char>(magic.bytes[1])) != 'l' ||
            std::tolower(static_cast<unsigned char>(magic.bytes[2])) != 'y')
            return;
        stream.get_next_line(format);
        skip_spaces_and_line_end(format);
        if (!token_match(format, "format")) return;
        const bool ascii = token_match(format, "ascii");
        if (!ascii && format.bytes.compare(0, 7, "binary_") != 0) return;
        const bool big_endian = !ascii && (format.at(7) == 'b' || format.at(7) == 'B');

        // PLY::DOM::ParseHeader.
        Buffer b;
        stream.get_next_line(b);
        std::vector<Element> elements;
        while (!b.bytes.empty()) {
            skip_comments(b);
            Element e;
            if (parse_element(stream, b, e)) elements.push_back(e);
            else if (token_match(b, "end_header")) break;
            else if (!stream.get_next_line(b)) throw PastTheBuffer{};  // assimp would loop here for ever
        }
        check_elements(elements, path);
        if (ascii) {
            skip_spaces_and_line_end(b);
            check_ascii(stream, b, elements, path, file.size());
        } else {
            // getNextBlock, less a first '\n' (taken for the end of "\r\n").
            // Its buffer is what is left of the cache; when nothing is, its
            // first byte is read through a null pointer (a crash: fuzzing
            // found a header ending on the 1 MiB cache's last byte).
            std::uint64_t at = stream.file_position();
            if (stream.next_block_empty())
                throw InputError(path, "the binary PLY header ends at byte " + std::to_string(at) +
                                           ", the end of assimp 5.2.5's 1 MiB buffer, which makes its reader crash");
            if (at < file.size() && *file.bytes(at, 1) == '\n') ++at;
            check_binary(file, std::min(at, file.size()), big_endian, elements, path);
        }
    } catch (const PastTheBuffer&) {
        throw InputError(path, "assimp 5.2.5 would read this PLY file past the end of its buffer (a corrupt file?)");
    }
}

}  // namespace fh
