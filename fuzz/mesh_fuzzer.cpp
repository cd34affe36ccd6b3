// libFuzzer target: the mesh loader (OBJ, PLY, STL, OFF through assimp) on
// arbitrary bytes (scripts/fuzz.sh). The first byte picks the format; the
// rest is written to a file of that extension in a temporary folder (the
// loader reads files: assimp and our header checks both open it). An accepted
// mesh must hold what load_mesh promises: finite vertices, indices in range,
// triangles of non-zero corners, normals one a vertex or none, colours one a
// vertex in [0, 1] or none.
//
// A PLY input whose first byte also has its top bit set is moved across the
// 1 MiB mark where assimp's line buffer reads its next block: comment lines
// go after its second line (the format line), so that the rest of it begins
// N bytes before the mark, N being its next two bytes (little-endian,
// 0 .. 65,535). Small inputs reach the block boundary that way, which
// meshes/ply_lists.cpp replays.
#include <algorithm>
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
        if (data[0] % 4 == 1 && (data[0] & 0x80) && size >= 3) {
            const std::string body(reinterpret_cast<const char*>(data + 3), size - 3);
            const std::size_t mark = (std::size_t(1) << 20) - (data[1] | std::size_t(data[2]) << 8);
            // Past the second line end, or the whole body when it has fewer.
            std::size_t head = 0;
            for (int line = 0; line < 2 && head < body.size(); ++line) {
                const std::size_t end = body.find('\n', head);
                head = end == std::string::npos ? body.size() : end + 1;
            }
            out << body.substr(0, head);
            // Comment lines of at most 64 KiB, the last at least 9 bytes long.
            for (std::size_t at = head; at < mark;) {
                std::size_t n = std::min<std::size_t>(mark - at, 65536);
                if (mark - at - n < 9 && mark - at > n) n -= 9;
                out << "comment " << std::string(n - 9, 'x') << '\n';
                at += n;
            }
            out << body.substr(head);
        } else {
            out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
        }
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
    if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) broken("colours not one a vertex");
    for (const fh::dvec3& c : mesh.colors)
        if (!(c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1)) broken("a colour outside [0, 1]");
    for (const fh::dvec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("a vertex not finite");
    for (const auto& t : mesh.triangles) {
        for (const std::uint32_t i : t)
            if (i >= mesh.positions.size()) broken("an index out of range");
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) broken("a triangle with a repeated corner");
    }
    return 0;
}
