#include "meshes/mesh_writer.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "files/atomic_file.h"
#include "text/input_error.h"

namespace fh {

namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::vector<std::uint8_t> ply(const std::vector<WorldTriangle>& triangles) {
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment firsthit export: world-space triangles\n"
                               "element vertex " + std::to_string(3 * triangles.size()) +
                               "\nproperty double x\nproperty double y\nproperty double z\n"
                               "element face " + std::to_string(triangles.size()) +
                               "\nproperty list uchar uint vertex_indices\nend_header\n";
    std::vector<std::uint8_t> out(header.begin(), header.end());
    out.reserve(out.size() + triangles.size() * (72 + 13));
    auto put = [&](const void* p, size_t n) {
        const auto* b = static_cast<const std::uint8_t*>(p);
        out.insert(out.end(), b, b + n);
    };
    for (const WorldTriangle& t : triangles)
        for (const dvec3& v : t) put(&v.x, 8), put(&v.y, 8), put(&v.z, 8);
    for (std::uint32_t i = 0; i < std::uint32_t(triangles.size()); ++i) {
        const std::uint8_t three = 3;
        const std::uint32_t f[3] = {3 * i, 3 * i + 1, 3 * i + 2};
        put(&three, 1);
        put(f, sizeof f);
    }
    return out;
}

std::vector<std::uint8_t> obj(const std::vector<WorldTriangle>& triangles) {
    std::string text = "# firsthit export: world-space triangles\n";
    char line[128];
    for (const WorldTriangle& t : triangles)
        for (const dvec3& v : t) {
            std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
            text += line;
        }
    for (size_t i = 0; i < triangles.size(); ++i) {
        std::snprintf(line, sizeof line, "f %zu %zu %zu\n", 3 * i + 1, 3 * i + 2, 3 * i + 3);
        text += line;
    }
    return {text.begin(), text.end()};
}

}  // namespace

void check_mesh_output(const std::string& path) {
    const std::string ext = extension_of(path);
    if (ext != ".ply" && ext != ".obj")
        throw UsageError("-o " + path + ": export writes .ply or .obj (by the name's extension)");
}

void write_mesh(const std::string& path, const std::vector<WorldTriangle>& triangles) {
    check_mesh_output(path);
    write_file_atomic(path, extension_of(path) == ".ply" ? ply(triangles) : obj(triangles));
}

}  // namespace fh
