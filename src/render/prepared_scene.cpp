#include "render/prepared_scene.h"

#include <chrono>

#include "render/flat_scene.h"

namespace fh {

PreparedScene::PreparedScene(const Scene& scene, const RenderSettings& settings, ThreadPool* pool)
    : settings_(settings) {
    const auto start = std::chrono::steady_clock::now();
    const EffectPlan plan = plan_effects(scene, settings.effects, settings.max_depth, settings.prune);
    if (settings.precision == Precision::float32)
        float_ = std::make_unique<FlatScene<float>>(FlatScene<float>::build(scene, plan, pool));
    else
        double_ = std::make_unique<FlatScene<double>>(FlatScene<double>::build(scene, plan, pool));
    build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

FrameResult PreparedScene::render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const {
    if (float_) return render_frame_as<float>(*float_, camera, sampling, pool);
    return render_frame_as<double>(*double_, camera, sampling, pool);
}

const EffectPlan& PreparedScene::plan() const { return float_ ? float_->plan : double_->plan; }
double PreparedScene::bvh_build_ms() const { return float_ ? float_->bvh.build_ms : double_->bvh.build_ms; }
int PreparedScene::bvh_nodes() const {
    return int(float_ ? float_->bvh.nodes.size() : double_->bvh.nodes.size());
}

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool) {
    return PreparedScene(scene, settings, pool).render(camera, pool);
}

}  // namespace fh
