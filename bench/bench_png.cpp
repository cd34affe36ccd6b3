// PNG encoding of one of the report's frames (Movie 1, frame 100, 800x800):
// the Sub filter, the run deflate and the chunks, as `firsthit frames`
// writes every frame.
//   build/bench/firsthit_bench --benchmark_filter=Png
#include <benchmark/benchmark.h>

#include "anim/movie.h"
#include "io/movie_loader.h"
#include "io/png_writer.h"
#include "render/render.h"

namespace fh {
namespace {

void BM_EncodePng(benchmark::State& state) {
    const Movie movie = load_movie(FIRSTHIT_SOURCE_DIR "/animations/movie1.yaml");
    const Image image = render_frame(movie.scene, camera_at(movie, 100), movie.scene.render,
                                     movie.scene.effects, nullptr)
                            .image;
    size_t bytes = 0;
    for (auto _ : state) bytes = encode_png(image).size();
    state.SetBytesProcessed(state.iterations() * std::int64_t(image.rgb.size()));
    state.counters["png_bytes"] = double(bytes);
}
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fh
