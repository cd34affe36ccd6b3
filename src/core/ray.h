// A ray: origin and unit direction (report section 2). Every ray the tracer
// makes has a unit direction; the intersection routines rely on it.
#pragma once

#include "core/vec.h"

namespace fh {

template <typename T>
struct Ray {
    Vec3<T> origin;
    Vec3<T> direction;  // unit length

    Vec3<T> at(T t) const { return origin + t * direction; }
};

}  // namespace fh
