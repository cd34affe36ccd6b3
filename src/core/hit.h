// The nearest intersection along one ray (tests, the viewer): how far, and
// on which primitive (render/primitive_ids.h numbers them).
#pragma once

#include "core/vec.h"

namespace fh {

template <typename T>
struct Hit {
    T t = kInfinity<T>;
    int prim = -1;  // its primitive id; -1: none

    bool found() const { return prim >= 0; }
};

}  // namespace fh
