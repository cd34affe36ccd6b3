#include "meshes/mesh_records.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>

#include "meshes/mesh_text.h"

namespace fh {

namespace {

using mesh_text::starts_with;

struct Word {
    std::string text;
    int column;  // 1-based
};
using Words = std::vector<Word>;

// A line's words; with `comments`, none from a '#' on.
Words words_of(const std::string& line, bool comments) {
    Words out;
    for (std::size_t i = 0; i < line.size();) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (comments && c == '#') break;
        if (std::isspace(c)) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) && !(comments && line[i] == '#'))
            ++i;
        out.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return out;
}

// Binary STL: 84 bytes of header and count, then 50 bytes a triangle (what
// assimp checks first, whatever the header's first word).
bool binary_stl(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[84] = {};
    if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return false;
    const std::uint64_t count = head[80] | head[81] << 8 | head[82] << 16 | std::uint64_t(head[83]) << 24;
    std::error_code ec;
    return std::filesystem::file_size(path, ec) == 84 + 50 * count;
}

enum class Kind { vertex, normal, face };

// Calls record(fields, line) for each record of `kind`, in file order, until
// it returns true. A record's fields: OBJ's after its keyword, STL's after
// `vertex`, an OFF or PLY vertex line's all, a face line's from its count
// of indices on. Binary files have none.
void for_each_record(const std::string& path, MeshFormat format, Kind kind,
                     const std::function<bool(const Words&, int)>& record) {
    if (format == MeshFormat::stl && (kind != Kind::vertex || binary_stl(path))) return;
    std::ifstream in(path, std::ios::binary);
    std::string line;
    int number = 0;
    auto next_line = [&]() {
        if (!std::getline(in, line)) return false;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        ++number;
        return true;
    };
    if (format == MeshFormat::obj || format == MeshFormat::stl) {
        const char* keyword =
            format == MeshFormat::stl ? "vertex" : (kind == Kind::vertex ? "v" : kind == Kind::normal ? "vn" : "f");
        while (next_line()) {
            Words w = words_of(line, format == MeshFormat::obj);
            if (w.empty() || w[0].text != keyword) continue;
            w.erase(w.begin());
            if (record(w, number)) return;
        }
        return;
    }
    // OFF and PLY: the header's counts, then one record a line.
    std::uint64_t vertices = 0, faces = 0;
    std::size_t face_skip = 0;  // PLY: scalar properties before a face's index list
    bool vertices_first = true;
    if (format == MeshFormat::off) {
        std::vector<std::string> head;  // keyword, [dimension,] counts
        std::size_t wanted = 2;
        while (head.size() < wanted && next_line()) {
            for (const Word& w : words_of(line, true)) {
                if (head.empty() && w.text.size() >= 3 && w.text.compare(w.text.size() - 3, 3, "OFF") == 0)
                    wanted = mesh_text::contains(w.text, "n") ? 4 : 3;
                head.push_back(w.text);
            }
        }
        if (head.size() < wanted) return;
        vertices = std::strtoull(head[wanted - 2].c_str(), nullptr, 10);
        faces = std::strtoull(head[wanted - 1].c_str(), nullptr, 10);
    } else {
        std::string element;
        bool list_seen = false;
        while (next_line()) {
            const Words w = words_of(line, false);
            if (w.empty()) continue;
            if (w[0].text == "end_header") break;
            if (w[0].text == "format" && w.size() > 1 && starts_with(w[1].text, "binary")) return;
            if (w[0].text == "element" && w.size() > 2) {
                element = w[1].text;
                const std::uint64_t count = std::strtoull(w[2].text.c_str(), nullptr, 10);
                if (element == "vertex") vertices = count, vertices_first = faces == 0;
                if (element == "face") faces = count;
                // Another element's lines before theirs: not followed. After: never read.
                if (element != "vertex" && element != "face" && (vertices == 0 || faces == 0)) return;
            } else if (w[0].text == "property" && element == "face" && !list_seen) {
                if (w.size() > 1 && w[1].text == "list") list_seen = true;
                else ++face_skip;
            }
        }
    }
    auto records = [&](std::uint64_t count, Kind of) {
        for (std::uint64_t k = 0; k < count && next_line();) {
            Words w = words_of(line, format == MeshFormat::off);
            if (w.empty()) continue;
            ++k;
            if (of == Kind::face) w.erase(w.begin(), w.begin() + std::ptrdiff_t(std::min(face_skip, w.size())));
            if ((of == Kind::face) == (kind == Kind::face) && record(w, number)) return true;
        }
        return false;
    };
    if (vertices_first) {
        if (!records(vertices, Kind::vertex)) records(faces, Kind::face);
    } else if (!records(faces, Kind::face)) {
        records(vertices, Kind::vertex);
    }
}

// As assimp reads a coordinate: a float (1e39 overflows to infinity).
float float_of(const Word& w) { return std::strtof(w.text.c_str(), nullptr); }

bool same(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

TextPosition nonfinite_vertex_position(const std::string& path, MeshFormat format, VertexPart part,
                                       long long index, const std::array<float, 3>* position) {
    TextPosition at;
    long long k = -1;
    const Kind kind = part == VertexPart::normal && format == MeshFormat::obj ? Kind::normal : Kind::vertex;
    for_each_record(path, format, kind, [&](const Words& w, int line) {
        ++k;
        if (index >= 0 && k != index) return false;
        if (position != nullptr) {
            if (w.size() < 3) return false;
            for (int i = 0; i < 3; ++i)
                if (!same(float_of(w[size_t(i)]), (*position)[size_t(i)])) return false;
        }
        const std::size_t checked = part != VertexPart::coordinates ? w.size() : std::min<std::size_t>(3, w.size());
        for (std::size_t i = 0; i < checked; ++i)
            if (!std::isfinite(float_of(w[i]))) {
                at = {line, w[i].column};
                return true;
            }
        return index >= 0;
    });
    return at;
}

TextPosition bad_face_index_position(const std::string& path, MeshFormat format) {
    long long vertices = 0;
    for_each_record(path, format, Kind::vertex, [&](const Words&, int) {
        ++vertices;
        return false;
    });
    TextPosition at;
    if (format == MeshFormat::obj) {
        // A relative index counts back from the vertices read so far.
        std::ifstream in(path, std::ios::binary);
        long long so_far = 0;
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            const Words w = words_of(line, true);
            if (w.empty()) continue;
            if (w[0].text == "v") ++so_far;
            if (w[0].text != "f") continue;
            for (std::size_t i = 1; i < w.size(); ++i) {
                const long long v = std::strtoll(w[i].text.c_str(), nullptr, 10);  // "v/vt/vn": v
                if (v == 0 || v > vertices || (v < 0 && so_far + v < 0)) return {number, w[i].column};
            }
        }
        return at;
    }
    for_each_record(path, format, Kind::face, [&](const Words& w, int line) {
        const std::size_t n = w.empty() ? 0 : std::strtoull(w[0].text.c_str(), nullptr, 10);
        for (std::size_t i = 1; i <= n && i < w.size(); ++i) {
            const long long v = std::strtoll(w[i].text.c_str(), nullptr, 10);
            if (v < 0 || v >= vertices) {
                at = {line, w[i].column};
                return true;
            }
        }
        return false;
    });
    return at;
}

}  // namespace fh
