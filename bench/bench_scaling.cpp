// Frame time against triangle count: the scene family of the scaling
// benchmark (scripts/bench_scaling.sh). An icosphere of 20 * 4^k triangles
// (k = 1 .. 8: 80 to 1.3 million) scaled to radius 3 at the origin, resting
// on a floor, Lambert + ambient + one directional light with shadows, camera
// at (0, -12, 6) looking along (0, 12, -6), 800 x 800, 1 sample per pixel.
// Prints one CSV row per size: triangles, prepare ms (flattening + BVH),
// BVH build ms, median render ms, rays per second, peak memory so far, and
// the instructions a frame executes (millions, all threads; empty where the
// kernel does not let a process count its own): the work apart from the
// time, which also holds the waits for memory.
//   firsthit_bench_scaling [--threads N] [--runs K] [--min-level K] [--max-level K] [--precision float|double]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <linux/perf_event.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "geometry/icosphere.h"
#include "render/prepared_scene.h"
#include "render/stats.h"
#include "render/thread_pool.h"

namespace {

using namespace fh;

Scene scaling_scene(int level) {
    Scene s;
    Material<double> grey;
    grey.ambient_color = grey.diffuse_color = grey.specular_color = dvec3(200);
    grey.ambient = 0.1;
    grey.diffuse = 0.9;
    grey.specular = 0;
    grey.phong_exponent = 1;
    s.material_names = {"grey"};
    s.materials = {grey};
    s.triangles = icosphere(level, 3.0, 0);
    s.planes.push_back({dvec3(0, 0, 1), -3.0, 0});  // the floor, z = -3
    s.ambient_lights.push_back({"ambient", dvec3(255), 0.006});
    s.directional_lights.push_back({"sun", dvec3(255), 0.004, glm::normalize(dvec3(-1, 1, -2))});
    Camera c;
    c.name = "camera";
    c.view_point = {0, -12, 6};
    c.look_at = {0, 12, -6};
    s.cameras = {c};
    return s;
}

// Instructions retired in user space by this process and the threads it
// starts after the counter (the pool's workers; the kernel sums them in).
class InstructionCounter {
public:
    InstructionCounter() {
        perf_event_attr a{};
        a.type = PERF_TYPE_HARDWARE;
        a.size = sizeof a;
        a.config = PERF_COUNT_HW_INSTRUCTIONS;
        a.exclude_kernel = 1;
        a.exclude_hv = 1;
        a.inherit = 1;
        fd_ = int(syscall(SYS_perf_event_open, &a, 0, -1, -1, 0));
    }
    ~InstructionCounter() {
        if (fd_ >= 0) close(fd_);
    }
    InstructionCounter(const InstructionCounter&) = delete;
    InstructionCounter& operator=(const InstructionCounter&) = delete;
    // -1: not counting.
    long long read() const {
        long long v = -1;
        return fd_ >= 0 && ::read(fd_, &v, sizeof v) == sizeof v ? v : -1;
    }

private:
    int fd_ = -1;
};

double peak_rss_mb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 0, runs = 5, min_level = 1, max_level = 8;
    Precision precision = Precision::float64;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--runs")) runs = std::max(1, std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--min-level")) min_level = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--max-level")) max_level = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--precision"))
            precision = std::strcmp(argv[i + 1], "float") ? Precision::float64 : Precision::float32;
    }
    const InstructionCounter instructions;  // before the pool: its workers count too
    ThreadPool pool(threads);
    RenderSettings settings;
    settings.precision = precision;
    settings.effects.specular = false;
    settings.effects.glazing = false;
    std::printf("triangles,prepare_ms,bvh_build_ms,bvh_nodes,render_ms,rays_per_second,peak_rss_mb,"
                "minstructions_per_frame\n");
    for (int level = std::max(1, min_level); level <= max_level; ++level) {
        const Scene scene = scaling_scene(level);
        const PreparedScene prepared(scene, settings, &pool);
        std::vector<double> ms;
        FrameResult r = prepared.render(scene.cameras[0], &pool);  // warm-up
        const long long before = instructions.read();
        for (int k = 0; k < runs; ++k) {
            r = prepared.render(scene.cameras[0], &pool);
            ms.push_back(r.render_ms);
        }
        const long long after = instructions.read();
        char per_frame[32] = "";
        if (before >= 0 && after >= before)
            std::snprintf(per_frame, sizeof per_frame, "%.2f", double(after - before) / runs / 1e6);
        const double m = median(ms);
        std::printf("%zu,%.3f,%.3f,%d,%.3f,%.4g,%.1f,%s\n", scene.triangles.size(), prepared.build_ms(),
                    prepared.bvh_build_ms(), prepared.bvh_nodes(), m, double(r.counts.total()) / (m / 1000),
                    peak_rss_mb(), per_frame);
        std::fflush(stdout);
    }
    return 0;
}
