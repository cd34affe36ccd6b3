// What a prepared scene asks of the tracer, whatever x86-64 level it was
// compiled for: the hot code -- ray generation, BVH walks, intersection,
// shading, colour conversion -- is built once per level (render/levels.h)
// behind this interface, and the rest of the program, built once, sees
// only it. Everything that crosses it (Scene, Camera, RenderSettings,
// FrameResult, ThreadPool) has the same layout at every level: no SIMD
// vector in it.
#pragma once

#include <cstddef>
#include <memory>

#include "render/render.h"

namespace fh {

// What a frame moved, against the scene prepared.
struct ShapeChanges {
    bool world = false;      // spheres, planes or triangles: the world's BVH is refitted
    bool instances = false;  // instances: their matrices and top BVH are redone
};

class PreparedTracer {
public:
    virtual ~PreparedTracer() = default;
    // See PreparedScene (render/prepared_scene.h), which forwards to these.
    virtual std::unique_ptr<PreparedTracer> for_frame(const Scene& frame, ShapeChanges moved,
                                                      ThreadPool* pool) const = 0;
    virtual FrameResult render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const = 0;
    virtual const EffectPlan& plan() const = 0;
    virtual double bvh_build_ms() const = 0;
    virtual int bvh_nodes() const = 0;
    virtual std::size_t instances() const = 0;
};

// One level's way in: the scene flattened for `settings` (precision,
// effects), its BVH built on `pool`. Each level's copy of the tracer has
// one, render/level_entry.cpp.
using PrepareTracer = PreparedTracer* (*)(const Scene& scene, const RenderSettings& settings, ThreadPool* pool);

// The tracer of the level this file was compiled for (render/flat_tracer.cpp).
std::unique_ptr<PreparedTracer> make_flat_tracer(const Scene& scene, const RenderSettings& settings,
                                                 ThreadPool* pool);

}  // namespace fh
