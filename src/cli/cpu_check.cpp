// Before anything else runs: does this CPU have the instruction sets the
// binary was built for (FIRSTHIT_ARCH)? A binary built with -march=native on
// a new cluster node and run on an older one would otherwise die of SIGILL
// somewhere in the tracer. Built for plain x86-64 (CMakeLists.txt), and run
// as a constructor of the highest priority, before other static initialisers
// that may already use the wider instructions.
#include <unistd.h>

#include <cstring>

namespace {

void say(const char* s) {
    if (write(STDERR_FILENO, s, std::strlen(s)) < 0) return;
}

__attribute__((constructor(101))) void check_cpu() {
#if defined(__x86_64__)
    __builtin_cpu_init();
    char missing[512] = "";
    auto need = [&](bool has, const char* name) {
        if (has) return;
        std::strcat(missing, " ");
        std::strcat(missing, name);
    };
    // One line per feature: __builtin_cpu_supports takes only a literal.
#define FH_NEED(macro, name) need(__builtin_cpu_supports(name), name)
#ifdef FIRSTHIT_NEEDS_SSE4_2
    FH_NEED(SSE4_2, "sse4.2");
#endif
#ifdef FIRSTHIT_NEEDS_POPCNT
    FH_NEED(POPCNT, "popcnt");
#endif
#ifdef FIRSTHIT_NEEDS_AVX
    FH_NEED(AVX, "avx");
#endif
#ifdef FIRSTHIT_NEEDS_AVX2
    FH_NEED(AVX2, "avx2");
#endif
#ifdef FIRSTHIT_NEEDS_FMA
    FH_NEED(FMA, "fma");
#endif
#ifdef FIRSTHIT_NEEDS_BMI
    FH_NEED(BMI, "bmi");
#endif
#ifdef FIRSTHIT_NEEDS_BMI2
    FH_NEED(BMI2, "bmi2");
#endif
#ifdef FIRSTHIT_NEEDS_F16C
    FH_NEED(F16C, "f16c");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512F
    FH_NEED(AVX512F, "avx512f");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512BW
    FH_NEED(AVX512BW, "avx512bw");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512CD
    FH_NEED(AVX512CD, "avx512cd");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512DQ
    FH_NEED(AVX512DQ, "avx512dq");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512VL
    FH_NEED(AVX512VL, "avx512vl");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512VBMI
    FH_NEED(AVX512VBMI, "avx512vbmi");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512VBMI2
    FH_NEED(AVX512VBMI2, "avx512vbmi2");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512IFMA
    FH_NEED(AVX512IFMA, "avx512ifma");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512VNNI
    FH_NEED(AVX512VNNI, "avx512vnni");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512BITALG
    FH_NEED(AVX512BITALG, "avx512bitalg");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512VPOPCNTDQ
    FH_NEED(AVX512VPOPCNTDQ, "avx512vpopcntdq");
#endif
#ifdef FIRSTHIT_NEEDS_AVX512BF16
    FH_NEED(AVX512BF16, "avx512bf16");
#endif
#ifdef FIRSTHIT_NEEDS_GFNI
    FH_NEED(GFNI, "gfni");
#endif
#ifdef FIRSTHIT_NEEDS_VAES
    FH_NEED(VAES, "vaes");
#endif
#ifdef FIRSTHIT_NEEDS_VPCLMULQDQ
    FH_NEED(VPCLMULQDQ, "vpclmulqdq");
#endif
#undef FH_NEED
    if (missing[0] == '\0') return;
    say("firsthit: error: this binary was built for " FIRSTHIT_ARCH " but this CPU lacks");
    say(missing);
    say("; rebuild it here, or for every node with cmake -DFIRSTHIT_ARCH=x86-64-v2 (any x86-64 CPU)\n");
    _exit(1);
#endif
}

}  // namespace
