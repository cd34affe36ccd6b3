// firsthit export FILE -o OUT.ply|OUT.obj: a frame's triangles in world
// space -- after groups, instances, hierarchy and animation -- for any mesh
// viewer to check a scene or an animation against.
#include <iostream>

#include "cli/commands.h"
#include "cli/job.h"
#include "files/atomic_file.h"
#include "files/input_files.h"
#include "meshes/mesh_writer.h"
#include "text/input_error.h"

namespace fh {

namespace {

// The most triangles export writes: 20 million make a 1.7 GB PLY file (and
// as much memory while it is written). A forest of 10,000 bunnies shows 754
// million: export its one bunny instead.
constexpr size_t kMaxExportTriangles = 20'000'000;

// Every triangle the scene shows, in the world: its own, then each
// instance's; and, when some instance's mesh has vertex colours, each
// vertex's colour (white where its mesh has none).
struct WorldMesh {
    std::vector<WorldTriangle> triangles, colors;
};
WorldMesh world_triangles(const Scene& scene, const std::string& file) {
    size_t total = scene.triangles.size();
    for (const Instance& i : scene.instances) total += scene.meshes[size_t(i.mesh)].mesh->triangles.size();
    if (total > kMaxExportTriangles)
        throw InputError(file, "shows " + std::to_string(total) + " triangles with its instances; export writes at "
                               "most " + std::to_string(kMaxExportTriangles));
    bool coloured = false;
    for (const Instance& i : scene.instances) coloured |= !scene.meshes[size_t(i.mesh)].mesh->colors.empty();
    WorldMesh out;
    out.triangles.reserve(total);
    if (coloured) out.colors.reserve(total);
    const WorldTriangle white{dvec3(1), dvec3(1), dvec3(1)};
    for (const Triangle<double>& t : scene.triangles) {
        if (t.degenerate()) continue;
        out.triangles.push_back({t.v0, t.v1, t.v2});
        if (coloured) out.colors.push_back(white);
    }
    for (const Instance& i : scene.instances) {
        const Mesh& mesh = *scene.meshes[size_t(i.mesh)].mesh;
        auto placed = [&](std::uint32_t v) { return dvec3(i.to_world * glm::dvec4(mesh.positions[v], 1.0)); };
        for (const auto& t : mesh.triangles) {
            out.triangles.push_back({placed(t[0]), placed(t[1]), placed(t[2])});
            if (!coloured) continue;
            out.colors.push_back(mesh.colors.empty() ? white
                                                     : WorldTriangle{mesh.colors[t[0]], mesh.colors[t[1]], mesh.colors[t[2]]});
        }
    }
    return out;
}

}  // namespace

int run_export(const Args& args) {
    const auto out = args.value("--output");
    if (!out || out->empty()) throw UsageError("export needs -o OUT.ply or -o OUT.obj");
    check_mesh_output(*out);
    check_output_file(*out);
    const Job job = job_from_args(args);
    check_not_an_input(*out);  // a mesh the scene has just read, say
    const Scene& scene = job.scene();
    const WorldMesh world = world_triangles(scene, job.file);
    const std::vector<WorldTriangle>& triangles = world.triangles;
    write_mesh(*out, triangles, world.colors);
    if (!args.has("--quiet")) {
        if (!scene.spheres().empty() || !scene.planes.empty() || !scene.shapes.of<Disk>().empty())
            std::cerr << job.file << ": warning: spheres, disks and planes are not triangles: left out\n";
        std::cerr << "wrote " << *out << " (" << triangles.size() << " triangles"
                  << (job.frame >= 0 ? ", frame " + std::to_string(job.frame) : std::string()) << ")\n";
    }
    return 0;
}

}  // namespace fh
