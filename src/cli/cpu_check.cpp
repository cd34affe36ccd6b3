// Before anything else runs: does this CPU have the instruction sets the
// binary was built for (FIRSTHIT_ARCH: for the default, x86-64-v2, which
// the start of the program needs before the tracer's level is chosen)? A binary built with -march=native on
// a new cluster node and run on an older one would otherwise die of SIGILL
// somewhere in the tracer. Built for plain x86-64 (CMakeLists.txt), and run
// as a constructor of the highest priority, before other static initialisers
// that may already use the wider instructions.
#include <unistd.h>

#include <cstring>

#ifndef FIRSTHIT_CPU_NEEDS
#define FIRSTHIT_CPU_NEEDS ""  // names, space-separated: what -march turned on
#endif
#ifndef FIRSTHIT_CPU_TARGET
#define FIRSTHIT_CPU_TARGET "x86-64"  // that -march
#endif

namespace {

void say(const char* s) {
    if (write(STDERR_FILENO, s, std::strlen(s)) < 0) return;
}

__attribute__((constructor(101))) void check_cpu() {
#if defined(__x86_64__)
    __builtin_cpu_init();
    struct Feature {
        const char* name;
        bool present;
    };
    // __builtin_cpu_supports takes only a literal: one entry per name.
#define FH_FEATURE(name) {name, __builtin_cpu_supports(name) != 0}
    const Feature features[] = {
        FH_FEATURE("sse4.2"),       FH_FEATURE("popcnt"),       FH_FEATURE("avx"),
        FH_FEATURE("avx2"),         FH_FEATURE("fma"),          FH_FEATURE("bmi"),
        FH_FEATURE("bmi2"),         FH_FEATURE("avx512f"),
        FH_FEATURE("avx512bw"),     FH_FEATURE("avx512cd"),     FH_FEATURE("avx512dq"),
        FH_FEATURE("avx512vl"),     FH_FEATURE("avx512vbmi"),   FH_FEATURE("avx512vbmi2"),
        FH_FEATURE("avx512ifma"),   FH_FEATURE("avx512vnni"),   FH_FEATURE("avx512bitalg"),
        FH_FEATURE("avx512vpopcntdq"), FH_FEATURE("avx512bf16"), FH_FEATURE("gfni"),
        FH_FEATURE("vpclmulqdq"),
#ifndef __clang__
        // Names clang 14 does not know (the sanitizer builds use clang):
        // there, a need for them goes unchecked.
        FH_FEATURE("f16c"),         FH_FEATURE("vaes"),
#endif
    };
#undef FH_FEATURE
    char missing[512] = "";
    const char* needs = FIRSTHIT_CPU_NEEDS;
    while (*needs) {
        const size_t n = std::strcspn(needs, " ");
        for (const Feature& f : features)
            if (!f.present && std::strlen(f.name) == n && std::strncmp(f.name, needs, n) == 0 &&
                std::strlen(missing) + n + 2 < sizeof missing) {
                std::strcat(missing, " ");
                std::strcat(missing, f.name);
            }
        needs += n + (needs[n] == ' ');
    }
    if (missing[0] == '\0') return;
    say("firsthit: error: this binary was built for " FIRSTHIT_CPU_TARGET " but this CPU lacks");
    say(missing);
    say("; rebuild it here, or for every node with the default cmake -DFIRSTHIT_ARCH=dispatch (any x86-64 CPU since "
        "about 2009, at its widest SIMD)\n");
    _exit(1);
#endif
}

}  // namespace
