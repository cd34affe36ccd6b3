// The bounded shapes a scene can hold besides triangles (which the tracer
// packs in blocks of its own) and planes (unbounded: never in a BVH). The
// order here is their numbering's: on equal distances the shape listed
// first wins. To add a shape: write it (geometry/disk.h is the model), list
// it here, and read it in the scene file (yaml/surface_reader.cpp);
// docs/architecture.md walks through it.
#pragma once

#include "geometry/disk.h"
#include "geometry/shape_list.h"
#include "geometry/sphere.h"

namespace fh {

template <typename T>
using BoundedShapes = ShapeArrays<T, ShapeList<Sphere, Disk>>;

}  // namespace fh
