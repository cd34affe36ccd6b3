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

// Small ones come from the ordinary heap: no 2 MiB per few nodes.
TEST(BigArray, SmallArraysAreOrdinary) {
    BigArray<double> small(10, 1.5);
    EXPECT_EQ(small.size(), 10u);
    EXPECT_DOUBLE_EQ(small[9], 1.5);
    small.push_back(2.5);
    EXPECT_DOUBLE_EQ(small.back(), 2.5);
}

}  // namespace
}  // namespace fh
