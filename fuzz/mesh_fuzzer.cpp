// libFuzzer target: the mesh loader (OBJ, PLY, STL, OFF through assimp) on
// arbitrary bytes (scripts/fuzz.sh). The first byte picks the format; the
// rest is written to a file of that extension in a temporary folder (the
// loader reads files: assimp and our header checks both open it). An accepted
// mesh must hold what load_mesh promises: finite vertices, indices in range,
// triangles of non-zero corners, normals one a vertex or none.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_common.h"
#include "meshes/mesh_loader.h"

namespace {

std::filesystem::path g_folder;

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "accepted mesh breaks a promise: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    g_folder = fh::fuzz::private_folder("mesh_fuzzer");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kExtensions[] = {".obj", ".ply", ".stl", ".off"};
    const std::string path = (g_folder / (std::string("mesh") + kExtensions[data[0] % 4])).string();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    fh::MeshData mesh;
    try {
        mesh = fh::load_mesh(path, 100'000);
    } catch (const fh::InputError& e) {
        fh::fuzz::check_message(e);
        return 0;
    }
    if (mesh.triangles.empty()) broken("no triangles");
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) broken("normals not one a vertex");
    for (const fh::dvec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("a vertex not finite");
    for (const auto& t : mesh.triangles) {
        for (const std::uint32_t i : t)
            if (i >= mesh.positions.size()) broken("an index out of range");
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) broken("a triangle with a repeated corner");
    }
    return 0;
}
