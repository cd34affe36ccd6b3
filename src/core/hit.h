// The nearest intersection along a ray, and the surface point it names.
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace fh {

enum class ShapeKind : std::uint8_t { none, sphere, plane, triangle };

// The nearest hit of one ray (tests, the viewer): which primitive, how far.
template <typename T>
struct Hit {
    T t = kInfinity<T>;
    ShapeKind kind = ShapeKind::none;
    int index = -1;  // into the scene's array of that kind

    bool found() const { return kind != ShapeKind::none; }
};

}  // namespace fh
