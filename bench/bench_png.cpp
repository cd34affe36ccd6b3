// PNG encoding of one of the report's frames (Movie 1, frame 100, 800x800):
// the Sub filter, the run deflate and the chunks, as `firsthit frames`
// writes every frame.
//   build/bench/firsthit_bench --benchmark_filter=Png
//   (after cmake --build build --target firsthit_bench: not in the default build)
#include <benchmark/benchmark.h>

#include "images/png_writer.h"
#include "report_frame.h"

namespace fh {
namespace {

void BM_EncodePng(benchmark::State& state) {
    const Image& image = report_frame();
    size_t bytes = 0;
    for (auto _ : state) bytes = encode_png(image).size();
    state.SetBytesProcessed(state.iterations() * std::int64_t(image.rgb.size()));
    state.counters["png_bytes"] = double(bytes);
}
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fh
