// The same frame is the same bytes however it is made: any --threads, any
// --shard layout (with or without --range), `frames` or `render --frame`.
#include <gtest/gtest.h>


#include <fstream>
#include <regex>

#include "cli/small_movie.h"
#include "support/off_file.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// A 48 x 40 copy of the report's scene (not square, not a multiple of the
// tile size), 2 samples per pixel, 10 frames with both lights of Movie 1.
fs::path movie_dir(const std::string& name) {
    return small_movie(name, 48, 40, 10, "movie.yaml", "render: {samples_per_pixel: 2}\n");
}

void run_frames(const fs::path& dir, const fs::path& out, const std::string& extra) {
    const auto r = run_firsthit("frames " + (dir / "movie.yaml").string() + " --quiet --out " + out.string() + " " +
                                extra);
    ASSERT_EQ(r.status, 0) << extra << ": " << r.err;
}

void expect_same_folder(const fs::path& a, const fs::path& b, const std::string& what) {
    ASSERT_EQ(frames_in(a), frames_in(b)) << what;
    for (const auto& name : frames_in(a)) EXPECT_EQ(slurp(a / name), slurp(b / name)) << what << ": " << name;
}

TEST(DeterminismCli, FramesAreTheSameBytesForAnyThreadsAndShardLayout) {
    const fs::path dir = movie_dir("determinism_frames");
    const fs::path ref = dir / "ref";
    run_frames(dir, ref, "--threads 1");
    ASSERT_EQ(frames_in(ref).size(), 10u);

    for (const int threads : {2, 3, 7}) {
        const fs::path out = dir / ("threads" + std::to_string(threads));
        run_frames(dir, out, "--threads " + std::to_string(threads));
        expect_same_folder(ref, out, "--threads " + std::to_string(threads));
    }
    // Shard layouts, each shard with its own thread count.
    for (const int n : {2, 3, 4, 10, 16}) {
        const fs::path out = dir / ("shards" + std::to_string(n));
        for (int k = 0; k < n; ++k)
            run_frames(dir, out, "--shard " + std::to_string(k) + "/" + std::to_string(n) + " --threads " +
                                     std::to_string(1 + k % 3));
        expect_same_folder(ref, out, std::to_string(n) + " shards");
    }
    // Ranges cut across shards.
    const fs::path mixed = dir / "mixed";
    for (const char* part : {"--range 0:4 --shard 0/2", "--range 0:4 --shard 1/2", "--range 4:10 --shard 0/3",
                             "--range 4:10 --shard 1/3 --threads 1", "--range 4:10 --shard 2/3 --threads 4"})
        run_frames(dir, mixed, part);
    expect_same_folder(ref, mixed, "ranges and shards");
}

TEST(DeterminismCli, RenderOfOneFrameIsTheSameForAnyThreads) {
    const fs::path dir = movie_dir("determinism_render");
    const fs::path ref = dir / "ref";
    run_frames(dir, ref, "--threads 2");
    for (const int frame : {0, 7}) {
        for (const int threads : {1, 2, 5, 16}) {
            const fs::path png = dir / ("f" + std::to_string(frame) + "_t" + std::to_string(threads) + ".png");
            const auto r = run_firsthit("render " + (dir / "movie.yaml").string() + " --frame " +
                                        std::to_string(frame) + " --threads " + std::to_string(threads) +
                                        " -o " + png.string());
            ASSERT_EQ(r.status, 0) << r.err;
            EXPECT_EQ(slurp(png), slurp(ref / ("frame_000" + std::to_string(frame) + ".png")))
                << "frame " << frame << ", --threads " << threads;
        }
    }
}

// The same over a mesh of 1280 triangles, which the tracer walks through its
// BVH (the report's seven primitives it tests whole): glazed, so reflection
// rays walk it too.
TEST(DeterminismCli, FramesOverAMeshAreTheSameBytesForAnyThreadsAndShards) {
    const fs::path dir = movie_dir("determinism_mesh");
    write_icosphere_off(dir / "ball.off", 3);
    std::string scene = slurp(dir / "scene.yaml");
    scene = std::regex_replace(scene, std::regex("surfaces:\n"),
                               "surfaces:\n  - {type: mesh, file: ball.off, material: metal,\n"
                               "     transform: {scale: 1.5, translate: [1, -2, 2]}}\n");
    std::ofstream(dir / "scene.yaml") << scene;
    const fs::path ref = dir / "ref";
    run_frames(dir, ref, "--threads 1");
    ASSERT_EQ(frames_in(ref).size(), 10u);
    const fs::path threads = dir / "threads3";
    run_frames(dir, threads, "--threads 3");
    expect_same_folder(ref, threads, "--threads 3");
    const fs::path shards = dir / "shards";
    for (int k = 0; k < 3; ++k) run_frames(dir, shards, "--shard " + std::to_string(k) + "/3 --threads 2");
    expect_same_folder(ref, shards, "3 shards");
    // And the mesh is in the picture: the frames differ from the scene without it.
    const fs::path plain = movie_dir("determinism_mesh_plain") / "ref";
    run_frames(plain.parent_path(), plain, "--threads 2");
    EXPECT_NE(slurp(ref / "frame_0000.png"), slurp(plain / "frame_0000.png"));
}

}  // namespace
}  // namespace fh::test
