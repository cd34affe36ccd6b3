#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "core/big_array.h"

namespace fh {
namespace {

// 2 MiB and more: on a 2 MiB boundary, where the kernel can back it with
// huge pages; the contents survive growth and copies like any vector's.
TEST(BigArray, LargeArraysStartOnAHugePageAndHoldTheirValues) {
    BigArray<std::int32_t> a(kHugePageBytes / sizeof(std::int32_t) + 3);
    std::iota(a.begin(), a.end(), 0);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % kHugePageBytes, 0u);
    a.resize(3 * a.size());  // reallocates
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % kHugePageBytes, 0u);
    EXPECT_EQ(a[kHugePageBytes / sizeof(std::int32_t) + 2], std::int32_t(kHugePageBytes / 4 + 2));
    const BigArray<std::int32_t> copy = a;
    EXPECT_EQ(copy, a);
}

// Small ones come from the ordinary heap (no 2 MiB for a few nodes), at
// their type's alignment: the walk's nodes are aligned to a cache line.
TEST(BigArray, SmallArraysAreOrdinaryAndAligned) {
    struct alignas(64) Line {
        double x[8];
    };
    BigArray<Line> small(3);
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % 64, 0u);
        small.push_back(Line{{double(k)}});
    }
    EXPECT_EQ(small.size(), 8u);
    EXPECT_DOUBLE_EQ(small.back().x[0], 4.0);
}

}  // namespace
}  // namespace fh
