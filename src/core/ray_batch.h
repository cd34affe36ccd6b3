// A batch of rays in structure-of-arrays form: the unit of work of the
// tracer. Every intersection loop runs one primitive against the whole batch
// (render/batch_intersect.h), which the compiler vectorises across rays:
// 4 doubles or 8 floats per AVX2 instruction. With the report's 9 primitives
// this beats any acceleration structure: there is nothing to skip.
#pragma once

#include "core/ray.h"

namespace fh {

template <typename T>
struct RayBatch {
    // Half a 16 x 16 tile at 1 sample per pixel: a wave of shading arrays
    // (render/shading.h) then stays within L1 and L2; 64 or 256 measured slower.
    static constexpr int kCapacity = 128;

    int size = 0;
    alignas(64) T ox[kCapacity];
    alignas(64) T oy[kCapacity];
    alignas(64) T oz[kCapacity];
    alignas(64) T dx[kCapacity];
    alignas(64) T dy[kCapacity];
    alignas(64) T dz[kCapacity];
    alignas(64) T t_max[kCapacity];  // shadow rays: where the light is

    bool full() const { return size == kCapacity; }

    FH_HOT_INLINE void set(int i, const Ray<T>& r, T limit = kInfinity<T>) {
        ox[i] = r.origin.x;
        oy[i] = r.origin.y;
        oz[i] = r.origin.z;
        dx[i] = r.direction.x;
        dy[i] = r.direction.y;
        dz[i] = r.direction.z;
        t_max[i] = limit;
    }

    void push(const Ray<T>& r, T limit = kInfinity<T>) { set(size++, r, limit); }

    FH_HOT_INLINE Ray<T> ray(int i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}}; }
};

}  // namespace fh
