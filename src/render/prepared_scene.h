// The scene ready to trace: flattened into the tracer's precision with only
// what the effect plan simulates (render/flat_scene.h) and its BVH built --
// once, for every frame that shares the scene's shapes. A movie whose camera
// moves prepares once and renders 300 frames; a frame whose lights or
// materials change re-flattens only those (for_frame), one whose shapes
// move refits the BVH of a copy of the shapes instead of building it anew,
// and one whose instances move redoes only their matrices and top BVH.
// The work is done by the tracer of the CPU's x86-64 level
// (render/prepared_tracer.h, render/levels.h).
#pragma once

#include <memory>

#include "render/prepared_tracer.h"
#include "render/render.h"

namespace fh {

class PreparedScene {
public:
    // pool: builds the BVH on it (nullptr: on the calling thread).
    PreparedScene(const Scene& scene, const RenderSettings& settings, ThreadPool* pool = nullptr);
    ~PreparedScene();

    // The same scene at another state of its lights, materials and shapes
    // (a movie's frame: same primitives, other values). The effect plan is
    // worked out for that state; what did not move is shared, the world's
    // shapes that moved are refitted (render/flat_geometry.h), instances
    // that moved placed anew (render/instance_set.h). pool: for a rebuild.
    PreparedScene for_frame(const Scene& frame, ShapeChanges moved, ThreadPool* pool = nullptr) const;
    PreparedScene(PreparedScene&&) noexcept;
    PreparedScene& operator=(PreparedScene&&) noexcept;

    // One frame through `camera`; pool == nullptr renders on the calling
    // thread (the frame pipeline runs one frame per worker that way). Safe
    // to call from several threads at once.
    FrameResult render(const Camera& camera, ThreadPool* pool) const { return render(camera, pool, settings_); }
    // The same with other sampling (samples per pixel, adaptive
    // anti-aliasing): a preview. What the plan fixed -- effects, depth,
    // precision -- stays as prepared.
    FrameResult render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const;

    const RenderSettings& settings() const { return settings_; }
    const EffectPlan& plan() const;
    double build_ms() const { return build_ms_; }  // flattening and the BVH (or its refit)
    double bvh_build_ms() const;                   // of which the BVH
    int bvh_nodes() const;
    size_t instances() const;       // placed meshes (the second level)

private:
    PreparedScene() = default;

    RenderSettings settings_;
    // The tracer of the x86-64 level in use (render/levels.h).
    std::unique_ptr<PreparedTracer> tracer_;
    double build_ms_ = 0;
};

}  // namespace fh
