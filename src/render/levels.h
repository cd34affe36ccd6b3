// Which copy of the tracer runs: the hot code is compiled once per x86-64
// level -- v2 (SSE4.2: 16-byte packets), v3 (AVX2 and FMA: 32 bytes), v4
// (AVX-512: 64 bytes) -- into one binary, and the widest level the CPU runs
// is chosen when the first scene is prepared. FIRSTHIT_ISA=v2|v3|v4 in the
// environment forces a lower one; a level the CPU lacks, or the binary does
// not hold, is refused. A build made for one CPU (FIRSTHIT_ARCH=host,
// native or x86-64-vN) holds that one level. Frames are a pure function
// of the scene and the level: double precision gives the same bytes at
// every level; float may differ in the last bit where FMA (v3, v4) fuses
// a multiply and an add.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/prepared_tracer.h"

namespace fh {

// The x86-64 level of this CPU: 4, 3, 2, or 1 (below v2).
int cpu_level();

// The level to run (2, 3 or 4): `requested` ("", "v2"/"x86-64-v2", ...)
// among the levels `compiled` in, on a CPU of level `cpu`. "" picks the
// widest both have. Throws std::invalid_argument with one line when the
// request is no level, a level the CPU lacks, or one the binary does not
// hold.
int choose_level(const std::string& requested, int cpu, const std::vector<int>& compiled);

// The levels this binary holds a tracer for.
const std::vector<int>& compiled_levels();

// The level in use (2, 3 or 4), chosen once (FIRSTHIT_ISA, the CPU).
// Throws as choose_level does; the command line asks for it first thing,
// so a bad FIRSTHIT_ISA is one line before any work.
int level_in_use();

// A level as people name it: "x86-64-v4".
std::string level_name(int level);

// `scene` prepared by the tracer of the level in use.
std::unique_ptr<PreparedTracer> prepare_tracer(const Scene& scene, const RenderSettings& settings, ThreadPool* pool);

}  // namespace fh
