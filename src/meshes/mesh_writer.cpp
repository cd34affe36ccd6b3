#include "meshes/mesh_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "files/atomic_file.h"
#include "files/file_names.h"
#include "text/input_error.h"

namespace fh {

namespace {

// A colour channel in [0, 1] as a byte.
std::uint8_t byte_of(double c) { return std::uint8_t(std::lround(255 * std::clamp(c, 0.0, 1.0))); }

std::vector<std::uint8_t> ply(const std::vector<WorldTriangle>& triangles, const std::vector<WorldTriangle>& colors) {
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment firsthit export: world-space triangles\n"
                               "element vertex " + std::to_string(3 * triangles.size()) +
                               "\nproperty double x\nproperty double y\nproperty double z\n" +
                               (colors.empty() ? "" : "property uchar red\nproperty uchar green\nproperty uchar blue\n") +
                               "element face " + std::to_string(triangles.size()) +
                               "\nproperty list uchar uint vertex_indices\nend_header\n";
    std::vector<std::uint8_t> out(header.begin(), header.end());
    out.reserve(out.size() + triangles.size() * (72 + (colors.empty() ? 0 : 9) + 13));
    auto put = [&](const void* p, size_t n) {
        const auto* b = static_cast<const std::uint8_t*>(p);
        out.insert(out.end(), b, b + n);
    };
    for (size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const dvec3& v = triangles[i][size_t(k)];
            put(&v.x, 8), put(&v.y, 8), put(&v.z, 8);
            if (colors.empty()) continue;
            const dvec3& c = colors[i][size_t(k)];
            out.insert(out.end(), {byte_of(c.x), byte_of(c.y), byte_of(c.z)});
        }
    for (std::uint32_t i = 0; i < std::uint32_t(triangles.size()); ++i) {
        const std::uint8_t three = 3;
        const std::uint32_t f[3] = {3 * i, 3 * i + 1, 3 * i + 2};
        put(&three, 1);
        put(f, sizeof f);
    }
    return out;
}

std::vector<std::uint8_t> obj(const std::vector<WorldTriangle>& triangles, const std::vector<WorldTriangle>& colors) {
    std::string text = "# firsthit export: world-space triangles\n";
    char line[192];
    for (size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const dvec3& v = triangles[i][size_t(k)];
            if (colors.empty()) {
                std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
            } else {
                const dvec3& c = colors[i][size_t(k)];
                auto unit = [](double x) { return std::clamp(x, 0.0, 1.0); };
                std::snprintf(line, sizeof line, "v %.17g %.17g %.17g %.9g %.9g %.9g\n", v.x, v.y, v.z, unit(c.x),
                              unit(c.y), unit(c.z));
            }
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
    const std::string ext = lowercase_extension(path);
    if (ext != ".ply" && ext != ".obj")
        throw UsageError("-o " + path + ": export writes .ply or .obj (by the name's extension)");
}

void write_mesh(const std::string& path, const std::vector<WorldTriangle>& triangles,
                const std::vector<WorldTriangle>& colors) {
    check_mesh_output(path);
    write_file_atomic(path, lowercase_extension(path) == ".ply" ? ply(triangles, colors) : obj(triangles, colors));
}

}  // namespace fh
