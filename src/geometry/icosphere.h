// A generated test mesh: the icosahedron's 20 triangles, each split in four
// `subdivisions` times with the new vertices pushed onto the sphere -- 20 *
// 4^k triangles, closed, every edge shared by exactly two (the shared
// vertices are computed identically on both sides). The scaling benchmark's
// scene family and the tests' closed mesh.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "geometry/triangle.h"

namespace fh {

inline std::vector<Triangle<double>> icosphere(int subdivisions, double radius, int material) {
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<dvec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                            {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (dvec3& p : v) p = glm::normalize(p);
    const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    std::vector<std::array<dvec3, 3>> tris;
    for (const auto& f : faces) tris.push_back({v[size_t(f[0])], v[size_t(f[1])], v[size_t(f[2])]});
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<std::array<dvec3, 3>> next;
        next.reserve(tris.size() * 4);
        for (const auto& t : tris) {
            const dvec3 a = glm::normalize(t[0] + t[1]), b = glm::normalize(t[1] + t[2]),
                        c = glm::normalize(t[2] + t[0]);
            next.push_back({t[0], a, c});
            next.push_back({t[1], b, a});
            next.push_back({t[2], c, b});
            next.push_back({a, b, c});
        }
        tris.swap(next);
    }
    std::vector<Triangle<double>> out;
    out.reserve(tris.size());
    for (const auto& t : tris)
        out.push_back(Triangle<double>::make(radius * t[0], radius * t[1], radius * t[2], material));
    return out;
}

}  // namespace fh
