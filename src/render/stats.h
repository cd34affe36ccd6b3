// Counts of what a render traced, per worker and then summed; the median of
// timings.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace fh {

struct RayCounts {
    std::uint64_t primary = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;
    std::uint64_t transmitted = 0;  // on through see-through surfaces (glTF's BLEND)
    std::uint64_t nonfinite_samples = 0;  // NaN or infinite before clamping; should stay 0

    std::uint64_t total() const { return primary + shadow + reflection + transmitted; }

    RayCounts& operator+=(const RayCounts& o) {
        primary += o.primary;
        shadow += o.shadow;
        reflection += o.reflection;
        transmitted += o.transmitted;
        nonfinite_samples += o.nonfinite_samples;
        return *this;
    }
};

// The median of timings: what bench and accuracy report.
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

}  // namespace fh
