// The nearest intersection along one ray (tests, the viewer): how far, and
// on which primitive (render/primitive_ids.h numbers them).
#pragma once

#include "core/vec.h"

namespace fh {

template <typename T>
struct Hit {
    T t = kInfinity<T>;
    int prim = -1;      // its primitive id (in its instance's mesh, if any); -1: none
    int instance = -1;  // its instance, or -1: one of the world's own primitives

    bool found() const { return prim >= 0; }
};

}  // namespace fh
