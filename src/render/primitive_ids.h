// One numbering of the primitives of the tracer's scene, used everywhere a
// primitive is named -- the BVH's leaves, a hit, a tile's visible list, the
// surfaces shading reads: the bounded shapes first, kind by kind in the
// order geometry/shapes.h lists them (spheres first), then the planes, then
// the triangles. On equal distances the lower id wins, so this order is
// also what decides ties. Planes are unbounded and stay outside the BVH;
// every other id is one of its inputs.
#pragma once

namespace fh {

struct PrimitiveIds {
    int shapes = 0;     // ids [0, shapes)
    int planes = 0;     // ids [shapes, shapes + planes)
    int triangles = 0;  // ids [shapes + planes, end())

    int first_plane() const { return shapes; }
    int first_triangle() const { return shapes + planes; }
    int end() const { return shapes + planes + triangles; }

    bool is_shape(int id) const { return id < shapes; }
    bool is_triangle(int id) const { return id >= first_triangle(); }

    int plane(int p) const { return first_plane() + p; }        // the id of plane p
    int triangle(int t) const { return first_triangle() + t; }  // the id of triangle t
    int plane_index(int id) const { return id - first_plane(); }
    int triangle_index(int id) const { return id - first_triangle(); }
};

}  // namespace fh
