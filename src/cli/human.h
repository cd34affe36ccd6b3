// Numbers for people: progress lines and summaries say "1 frame in 1.1 ms"
// and "24 frames in 2.3 s (10 frames/s)", not "0.00114133 s". (The key:
// value lines of --stats and bench keep full precision, for scripts.)
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace fh {

// Two significant digits below 10, whole numbers above: 1.1, 12, 340.
inline std::string human_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, std::fabs(v) < 9.95 ? "%.1f" : "%.0f", v);
    return buf;
}

// 1.1 ms, 340 ms, 2.3 s, 45 s, 2 min 05 s, 1 h 02 min.
inline std::string human_duration(double seconds) {
    if (seconds < 0.9995) return human_number(seconds * 1000) + " ms";
    if (seconds < 59.5) return human_number(seconds) + " s";
    char buf[48];
    const long s = std::lround(seconds), m = std::lround(seconds / 60);
    if (s < 3600) std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%ld h %02ld min", m / 60, m % 60);
    return buf;
}

// "1 frame", "24 frames".
inline std::string plural(long long n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace fh
