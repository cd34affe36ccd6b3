// Test meshes as files: the closed icosphere (geometry/icosphere.h) written
// as OFF, each triangle with its own three vertices (the reader joins them).
#pragma once

#include <filesystem>
#include <fstream>
#include <vector>

#include "geometry/icosphere.h"

namespace fh::test {

inline void write_icosphere_off(const std::filesystem::path& path, int subdivisions, double radius = 1.0) {
    std::ofstream off(path);
    const std::vector<Triangle<double>> tris = icosphere(subdivisions, radius, 0);
    off << "OFF\n" << 3 * tris.size() << " " << tris.size() << " 0\n";
    off.precision(17);
    for (const auto& t : tris)
        for (const dvec3& v : {t.v0, t.v1, t.v2}) off << v.x << " " << v.y << " " << v.z << "\n";
    for (size_t i = 0; i < tris.size(); ++i) off << "3 " << 3 * i << " " << 3 * i + 1 << " " << 3 * i + 2 << "\n";
}

}  // namespace fh::test
