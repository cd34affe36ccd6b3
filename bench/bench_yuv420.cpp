// RGB to yuv420p (video/yuv420.h) of one of the report's frames (Movie 1,
// frame 100, 800x800), as `make movies` converts every frame on the render
// threads before streaming it to the encoder.
//   build/bench/firsthit_bench --benchmark_filter=Yuv
//   (after cmake --build build --target firsthit_bench: not in the default build)
#include <benchmark/benchmark.h>

#include "video/yuv420.h"
#include "report_frame.h"

namespace fh {
namespace {

void BM_ToYuv420p(benchmark::State& state) {
    const Image& image = report_frame();
    for (auto _ : state) benchmark::DoNotOptimize(to_yuv420p(image).data());
    state.SetBytesProcessed(state.iterations() * std::int64_t(image.rgb.size()));
}
BENCHMARK(BM_ToYuv420p)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fh
