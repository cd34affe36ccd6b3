// The scene ready to trace: flattened into the tracer's precision with only
// what the effect plan simulates (render/flat_scene.h) and its BVH built --
// once, for every frame that shares the scene, its lights and the settings.
// A movie whose camera moves prepares once and renders 300 frames; only the
// camera is per frame.
#pragma once

#include <memory>

#include "render/render.h"

namespace fh {

template <typename T>
struct FlatScene;

class PreparedScene {
public:
    // pool: builds the BVH on it (nullptr: on the calling thread).
    PreparedScene(const Scene& scene, const RenderSettings& settings, ThreadPool* pool = nullptr);
    ~PreparedScene();
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
    double build_ms() const { return build_ms_; }  // flattening and the BVH
    double bvh_build_ms() const;
    int bvh_nodes() const;

private:
    RenderSettings settings_;
    std::unique_ptr<FlatScene<float>> float_;
    std::unique_ptr<FlatScene<double>> double_;
    double build_ms_ = 0;
};

}  // namespace fh
