#include "render/prepared_scene.h"

#include <chrono>

#include "render/levels.h"

namespace fh {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreparedScene::PreparedScene(const Scene& scene, const RenderSettings& settings, ThreadPool* pool)
    : settings_(settings) {
    const auto start = std::chrono::steady_clock::now();
    tracer_ = prepare_tracer(scene, settings, pool);
    build_ms_ = ms_since(start);
}

PreparedScene PreparedScene::for_frame(const Scene& frame, ShapeChanges moved, ThreadPool* pool) const {
    const auto start = std::chrono::steady_clock::now();
    PreparedScene p;
    p.settings_ = settings_;
    p.tracer_ = tracer_->for_frame(frame, moved, pool);
    p.build_ms_ = ms_since(start);
    return p;
}

PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

FrameResult PreparedScene::render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const {
    return tracer_->render(camera, pool, sampling);
}

const EffectPlan& PreparedScene::plan() const { return tracer_->plan(); }
double PreparedScene::bvh_build_ms() const { return tracer_->bvh_build_ms(); }
int PreparedScene::bvh_nodes() const { return tracer_->bvh_nodes(); }
size_t PreparedScene::instances() const { return tracer_->instances(); }

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool) {
    return PreparedScene(scene, settings, pool).render(camera, pool);
}

}  // namespace fh
