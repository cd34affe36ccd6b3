// Cameras (report 5). The report's look_at is a direction, not a point:
//     w = normalize(-look_at), u = normalize(up x w), v = w x u.
// The image plane is 20 units tall: half_height = 10, half_width = 10 * width / height,
// and pixel (i, j) (column i, row j from the top) sits at
//     x = -half_width + (2 half_width / width)(i + 1/2),  y = half_height - (2 half_height / height)(j + 1/2).
// Orthographic: origin = view_point + x u + y v, direction = -w.
// Perspective:  origin = view_point, direction = normalize(-d w + x u + y v).
// (The report writes u y + v x, which transposes the image; docs/deviations.md.)
#pragma once

#include <string>

#include "core/packet.h"

namespace fh {

enum class Projection { orthographic, perspective };

// A camera as a scene or movie describes it.
struct Camera {
    std::string name;
    Projection projection = Projection::perspective;
    int width = 800;
    int height = 800;
    dvec3 view_point{0};
    dvec3 look_at{0, 0, -1};  // a direction
    dvec3 up{0, 0, 1};
    double projection_distance = 10;
    // Half the image plane's height: the report's 10. An orthographic camera
    // sees 2 half_height world units from the top of the image to the
    // bottom; a perspective one sees them at projection_distance (a glTF
    // camera sets both from its yfov, or its ymag).
    double half_height = 10;
    int node = -1;  // a glTF camera: the scene node that places it (scene/node.h)
};

struct CameraBasis {
    dvec3 u, v, w;
    bool up_was_parallel = false;  // the fallback rule below was used
};

// The orthonormal basis of a camera. When `up` is parallel to the view
// direction (up x w vanishes), the documented fallback is to use, as `up`, the
// coordinate axis least aligned with w (x before y before z on ties).
// look_at must be non-zero (the loaders reject a zero one).
CameraBasis camera_basis(const dvec3& look_at, const dvec3& up);

// Camera rays in the tracer's scalar type, from continuous pixel coordinates
// (px, py): px in [0, width) from the left, py in [0, height) from the top;
// the centre of pixel (i, j) is (i + 0.5, j + 0.5).
template <typename T>
class CameraRays {
public:
    explicit CameraRays(const Camera& cam) {
        const CameraBasis b = camera_basis(cam.look_at, cam.up);
        perspective_ = cam.projection == Projection::perspective;
        eye_ = Vec3<T>(cam.view_point);
        u_ = Vec3<T>(b.u);
        v_ = Vec3<T>(b.v);
        const double half_height = cam.half_height;
        const double half_width = cam.half_height * cam.width / cam.height;
        x0_ = T(-half_width);
        y0_ = T(half_height);
        dx_ = T(2 * half_width / cam.width);
        dy_ = T(2 * half_height / cam.height);
        forward_ = Vec3<T>(-b.w * (perspective_ ? cam.projection_distance : 1.0));
    }

    // The camera rays through the pixel positions of each lane.
    FH_HOT_INLINE RayPacket<T> generate(const Lanes<T>& px, const Lanes<T>& py) const {
        const Vec3Lanes<T> offset = (x0_ + dx_ * px) * u_ + (y0_ - dy_ * py) * v_;
        if (perspective_) return {Vec3Lanes<T>::splat(eye_), normalize(forward_ + offset)};
        return {eye_ + offset, Vec3Lanes<T>::splat(forward_)};
    }

    // One ray: the packet formula with that position in every lane.
    Ray<T> generate(T px, T py) const { return generate(splat(px), splat(py)).lane(0); }

private:
    bool perspective_ = true;
    Vec3<T> eye_, u_, v_, forward_;
    T x0_, y0_, dx_, dy_;
};

}  // namespace fh
