// Two points or vectors equal to a tolerance, each axis checked (and
// reported) on its own.
#pragma once

#include <gtest/gtest.h>

#include "core/vec.h"

namespace fh::test {

inline void expect_vec_near(const dvec3& got, const dvec3& want, double tol = 1e-12) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

}  // namespace fh::test
