#include "render/levels.h"

#include <cstdlib>
#include <stdexcept>

namespace fh {

// The levels' entries (render/level_entry.cpp); FIRSTHIT_HAS_Vn says which
// this binary holds (CMakeLists.txt).
extern "C" {
#ifdef FIRSTHIT_HAS_V2
PreparedTracer* firsthit_tracer_v2(const Scene&, const RenderSettings&, ThreadPool*);
#endif
#ifdef FIRSTHIT_HAS_V3
PreparedTracer* firsthit_tracer_v3(const Scene&, const RenderSettings&, ThreadPool*);
#endif
#ifdef FIRSTHIT_HAS_V4
PreparedTracer* firsthit_tracer_v4(const Scene&, const RenderSettings&, ThreadPool*);
#endif
}

namespace {

PrepareTracer entry(int level) {
    switch (level) {
#ifdef FIRSTHIT_HAS_V2
    case 2: return firsthit_tracer_v2;
#endif
#ifdef FIRSTHIT_HAS_V3
    case 3: return firsthit_tracer_v3;
#endif
#ifdef FIRSTHIT_HAS_V4
    case 4: return firsthit_tracer_v4;
#endif
    default: return nullptr;
    }
}

// What each level needs beyond the one below, as the CPU is asked.
const char* missing_for(int level) {
    return level == 4 ? "AVX-512 (avx512f, bw, cd, dq, vl)" : level == 3 ? "AVX2, FMA, BMI1 and BMI2" : "SSE4.2 and POPCNT";
}

}  // namespace

int cpu_level() {
#if defined(__x86_64__)
    __builtin_cpu_init();
    const bool v2 = __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
    const bool v3 = v2 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                    __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                    __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                    __builtin_cpu_supports("avx512vl");
    return v4 ? 4 : v3 ? 3 : v2 ? 2 : 1;
#else
    return 2;  // not x86-64: the one tracer the compiler's default target gets
#endif
}

int choose_level(const std::string& requested, int cpu, const std::vector<int>& compiled) {
    auto holds = [&](int l) {
        for (const int c : compiled)
            if (c == l) return true;
        return false;
    };
    std::string holding;
    for (const int c : compiled) holding += (holding.empty() ? "v" : ", v") + std::to_string(c);
    if (requested.empty()) {
        for (int l = 4; l >= 2; --l)
            if (holds(l) && l <= cpu) return l;
        throw std::invalid_argument("this CPU runs none of the x86-64 levels this binary holds (" + holding +
                                    "); it lacks " + missing_for(compiled.empty() ? 2 : compiled.front()));
    }
    int level = 0;
    for (int l = 2; l <= 4; ++l)
        if (requested == "v" + std::to_string(l) || requested == level_name(l)) level = l;
    if (level == 0)
        throw std::invalid_argument("FIRSTHIT_ISA=" + requested + ": not an x86-64 level (v2, v3 or v4)");
    if (!holds(level))
        throw std::invalid_argument("FIRSTHIT_ISA=" + requested + ": this binary holds " + holding +
                                    " only (it was built with FIRSTHIT_ARCH for one CPU)");
    if (level > cpu)
        throw std::invalid_argument("FIRSTHIT_ISA=" + requested + ": this CPU lacks " + missing_for(level) +
                                    "; it runs up to " + (cpu >= 2 ? "v" + std::to_string(cpu) : "none of them"));
    return level;
}

const std::vector<int>& compiled_levels() {
    static const std::vector<int> levels = [] {
        std::vector<int> out;
        for (int l = 2; l <= 4; ++l)
            if (entry(l)) out.push_back(l);
        return out;
    }();
    return levels;
}

std::string level_name(int level) { return "x86-64-v" + std::to_string(level); }

int level_in_use() {
    // FIRSTHIT_ISA's level, or the widest. (A throw leaves it unset: the
    // next call asks again, and throws again.)
    static const int level = [] {
        const char* requested = std::getenv("FIRSTHIT_ISA");
        return choose_level(requested ? requested : "", cpu_level(), compiled_levels());
    }();
    return level;
}

std::unique_ptr<PreparedTracer> prepare_tracer(const Scene& scene, const RenderSettings& settings, ThreadPool* pool) {
    return std::unique_ptr<PreparedTracer>(entry(level_in_use())(scene, settings, pool));
}

}  // namespace fh
