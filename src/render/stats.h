// Counts of what a render traced, per worker and then summed.
#pragma once

#include <cstdint>

namespace fh {

struct RayCounts {
    std::uint64_t primary = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;
    std::uint64_t nonfinite_samples = 0;  // NaN or infinite before clamping; should stay 0

    std::uint64_t total() const { return primary + shadow + reflection; }

    RayCounts& operator+=(const RayCounts& o) {
        primary += o.primary;
        shadow += o.shadow;
        reflection += o.reflection;
        nonfinite_samples += o.nonfinite_samples;
        return *this;
    }
};

}  // namespace fh
