// Small glTF 2.0 files written by the tests themselves: a binary buffer built
// from little-endian numbers (each run of numbers one buffer view), the JSON
// around it with the buffer as a base64 `data:` URI (or beside it, or in a
// GLB), and a check that a load fails with one InputError naming the file.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/vec.h"
#include "text/input_error.h"

namespace fh::gltf_test {

// glTF's component types (specification 3.6.2.2).
inline constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
                     kUnsignedInt = 5125, kFloat = 5126;

// sin 45° = cos 45°: the quaternions of quarter turns.
inline constexpr double kHalfSqrt2 = 0.70710678118654752440;

inline void put_le(std::string& out, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out += char((v >> (8 * i)) & 0xff);
}

inline std::string le32(std::uint32_t v) {
    std::string s;
    put_le(s, v, 4);
    return s;
}

// The standard base64 alphabet, '=' padded (RFC 4648 section 4).
inline std::string base64(const std::string& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        std::uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k)
            group = (group << 8) | (k < n ? std::uint8_t(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

inline std::string data_uri(const std::string& bytes) { return "data:application/octet-stream;base64," + base64(bytes); }

// One binary buffer; every add_* appends its numbers (little-endian, from a
// 4-byte boundary) as a new buffer view and returns the view's index.
class Bin {
public:
    int f32(const std::vector<float>& v, int stride = 0) {
        std::string b;
        for (const float x : v) put_le(b, std::bit_cast<std::uint32_t>(x), 4);
        return raw(b, stride);
    }
    int u8(const std::vector<int>& v, int stride = 0) { return ints(v, 1, stride); }
    int i8(const std::vector<int>& v, int stride = 0) { return ints(v, 1, stride); }
    int u16(const std::vector<int>& v, int stride = 0) { return ints(v, 2, stride); }
    int i16(const std::vector<int>& v, int stride = 0) { return ints(v, 2, stride); }
    int u32(const std::vector<std::uint32_t>& v, int stride = 0) {
        std::string b;
        for (const std::uint32_t x : v) put_le(b, x, 4);
        return raw(b, stride);
    }
    int raw(const std::string& b, int stride = 0) {
        while (bytes_.size() % 4) bytes_ += '\0';
        std::string view = "{\"buffer\": 0, \"byteOffset\": " + std::to_string(bytes_.size()) +
                           ", \"byteLength\": " + std::to_string(b.size());
        if (stride) view += ", \"byteStride\": " + std::to_string(stride);
        views_.push_back(view + "}");
        bytes_ += b;
        return int(views_.size()) - 1;
    }

    const std::string& bytes() const { return bytes_; }
    std::string views_json() const {
        std::string s;
        for (const std::string& v : views_) s += (s.empty() ? "" : ", ") + v;
        return "[" + s + "]";
    }

private:
    int ints(const std::vector<int>& v, int size, int stride) {
        std::string b;
        for (const int x : v) put_le(b, std::uint64_t(std::int64_t(x)), size);  // two's complement
        return raw(b, stride);
    }

    std::string bytes_;
    std::vector<std::string> views_;
};

// Where a file's buffer is: a data: URI, a file beside it (`uri`), or a
// GLB's binary chunk (no uri).
struct BufferAt {
    enum Kind { data, file, glb } kind = data;
    std::string uri;
};
inline BufferAt in_glb() { return {BufferAt::glb, ""}; }
inline BufferAt in_file(std::string uri) { return {BufferAt::file, std::move(uri)}; }

// A glTF file's JSON: the asset, `bin` as buffer 0 with its views, and `body`
// (the rest of the top-level members, without braces).
inline std::string gltf_json(const std::string& body, const Bin& bin = Bin(), const BufferAt& at = {}) {
    std::string s = "{\"asset\": {\"version\": \"2.0\"}";
    if (!bin.bytes().empty()) {
        s += ",\n\"buffers\": [{\"byteLength\": " + std::to_string(bin.bytes().size());
        if (at.kind == BufferAt::data) s += ", \"uri\": \"" + data_uri(bin.bytes()) + "\"";
        if (at.kind == BufferAt::file) s += ", \"uri\": \"" + at.uri + "\"";
        s += "}],\n\"bufferViews\": " + bin.views_json();
    }
    if (!body.empty()) s += ",\n" + body;
    return s + "\n}";
}

// A GLB (specification 4.4): the 12-byte header, the JSON chunk padded with
// spaces, and the binary chunk (when there is one) padded with zeros.
inline std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    const size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    std::string out = "glTF" + le32(2) + le32(std::uint32_t(total));
    out += le32(std::uint32_t(json.size())) + "JSON" + json;
    if (!bin.empty()) out += le32(std::uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
    return out;
}

// One accessor's JSON: `count` elements of `type` ("SCALAR", "VEC3", ...) of
// `component_type` in buffer view `view`; `more`: further members, each
// starting with a comma (", \"normalized\": true").
inline std::string accessor(int view, int component_type, size_t count, const std::string& type,
                            const std::string& more = "") {
    return "{\"bufferView\": " + std::to_string(view) + ", \"componentType\": " + std::to_string(component_type) +
           ", \"count\": " + std::to_string(count) + ", \"type\": \"" + type + "\"" + more + "}";
}

// An accessor's sparse member (for accessor()'s `more`): `count` elements
// at the indices in view `indices` (of `index_type`) take the values in view
// `values`.
inline std::string sparse(int count, int indices, int index_type, int values) {
    return ", \"sparse\": {\"count\": " + std::to_string(count) + ", \"indices\": {\"bufferView\": " +
           std::to_string(indices) + ", \"componentType\": " + std::to_string(index_type) +
           "}, \"values\": {\"bufferView\": " + std::to_string(values) + "}}";
}

// A scene of one node holding mesh 0, a triangle (0,0,0) (1,0,0) (0,1,0);
// `bin` gets its positions as view `view`.
inline std::string triangle_body(Bin& bin) {
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    return R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"accessors": [{"bufferView": )" + std::to_string(view) + R"(, "componentType": 5126, "count": 3, "type": "VEC3"}])";
}

// Mesh 0, the triangle (0,0,0) (1,0,0) (0,1,0) read by accessor 0, and
// `more` accessors after it (", {...}", from index 1); the caller adds the
// scenes and nodes.
inline std::string triangle_mesh(Bin& bin, const std::string& more = "") {
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    return R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [)" +
           accessor(view, kFloat, 3, "VEC3") + more + "]";
}

// A file of one node holding mesh 0, whose primitives and accessors are given.
inline std::string one_mesh(const Bin& bin, const std::string& primitives, const std::string& accessors) {
    return gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], "meshes": [{"primitives": [)" + primitives +
                         "]}], \"accessors\": [" + accessors + "]",
                     bin);
}

// JSON items joined by commas: "a, b, c".
inline std::string joined(std::initializer_list<std::string> items) {
    std::string s;
    for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

// An animation's channel (sampler `sampler` driving `path` of `node`) and
// sampler (times from accessor `input`, values from `output`); the
// "animations" member of one animation of such channels and samplers.
inline std::string channel(int sampler, int node, const std::string& path) {
    return "{\"sampler\": " + std::to_string(sampler) + ", \"target\": {\"node\": " + std::to_string(node) +
           ", \"path\": \"" + path + "\"}}";
}
inline std::string sampler(int input, int output, const std::string& interpolation) {
    return "{\"input\": " + std::to_string(input) + ", \"output\": " + std::to_string(output) +
           ", \"interpolation\": \"" + interpolation + "\"}";
}

inline std::string animation(const std::string& channels, const std::string& samplers) {
    return "\"animations\": [{\"channels\": [" + channels + "], \"samplers\": [" + samplers + "]}]";
}

inline void expect_vec(const dvec3& got, const dvec3& want, double tol = 1e-12) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(got[i], want[i], tol) << "component " << i << " of (" << got.x << ", " << got.y << ", " << got.z
                                          << ")";
}

// `got` against a matrix written by hand, row by row.
inline void expect_matrix(const glm::dmat4& got, const std::array<std::array<double, 4>, 4>& rows,
                          double tol = 1e-12) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(got[c][r], rows[size_t(r)][size_t(c)], tol) << "row " << r << ", column " << c;
}

// `load` must throw one InputError naming `file`, on one line, whose
// message holds `phrase`; returns the error for further checks.
inline InputError expect_input_error(const std::function<void()>& load, const std::string& file,
                                     const std::string& phrase) {
    try {
        load();
    } catch (const InputError& e) {
        const std::string line = e.formatted();
        EXPECT_EQ(e.file(), file);
        EXPECT_EQ(line.rfind(file, 0), 0u) << line;
        EXPECT_NE(line.find(": error: "), std::string::npos) << line;
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << "message: " << line << "\nwanted: " << phrase;
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return InputError(file, "");
    }
    ADD_FAILURE() << "no error; wanted one holding: " << phrase;
    return InputError(file, "");
}

// A folder of its own under the system's temporary folder, removed after.
struct TempFolder {
    std::filesystem::path path;
    explicit TempFolder(const std::string& name) {
        static int counter = 0;
        path = std::filesystem::temp_directory_path() /
               ("firsthit_gltf_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::string& content) const {
        const std::filesystem::path p = path / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary | std::ios::trunc) << content;
        return p.string();
    }
};

}  // namespace fh::gltf_test
