#include "render/prepared_scene.h"

#include <chrono>
#include <type_traits>

#include "render/flat_scene.h"

namespace fh {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PreparedScene::PreparedScene(const Scene& scene, const RenderSettings& settings, ThreadPool* pool)
    : settings_(settings) {
    const auto start = std::chrono::steady_clock::now();
    const EffectPlan plan = plan_effects(scene, settings.effects, settings.max_depth, settings.prune);
    if (settings.precision == Precision::float32)
        float_ = std::make_unique<FlatScene<float>>(FlatScene<float>::build(scene, plan, pool));
    else
        double_ = std::make_unique<FlatScene<double>>(FlatScene<double>::build(scene, plan, pool));
    build_ms_ = ms_since(start);
}

PreparedScene PreparedScene::for_frame(const Scene& frame, ShapeChanges moved, ThreadPool* pool) const {
    const auto start = std::chrono::steady_clock::now();
    PreparedScene p;
    p.settings_ = settings_;
    const EffectPlan plan = plan_effects(frame, settings_.effects, settings_.max_depth, settings_.prune);
    auto next = [&](const auto& flat) {
        using Flat = std::decay_t<decltype(*flat)>;
        auto geometry = flat->geometry;
        if (moved.world)
            geometry = std::make_shared<const typename decltype(geometry)::element_type>(geometry->refit(frame, pool));
        auto instances = flat->instances;
        if (moved.instances && instances) instances = instances->moved(frame, pool);
        return std::make_unique<Flat>(Flat::build(frame, plan, std::move(geometry), std::move(instances)));
    };
    if (float_) p.float_ = next(float_);
    else p.double_ = next(double_);
    p.build_ms_ = ms_since(start);
    return p;
}

PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

FrameResult PreparedScene::render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const {
    if (float_) return render_frame_as<float>(*float_, camera, sampling, pool);
    return render_frame_as<double>(*double_, camera, sampling, pool);
}

const EffectPlan& PreparedScene::plan() const { return float_ ? float_->plan : double_->plan; }
double PreparedScene::bvh_build_ms() const {
    return float_ ? float_->geometry->bvh.build_ms : double_->geometry->bvh.build_ms;
}
int PreparedScene::bvh_nodes() const {
    return int(float_ ? float_->geometry->bvh.nodes.size() : double_->geometry->bvh.nodes.size());
}

size_t PreparedScene::instances() const {
    if (float_) return float_->instances ? float_->instances->instances.size() : 0;
    return double_->instances ? double_->instances->instances.size() : 0;
}
double PreparedScene::instances_update_ms() const {
    if (float_) return float_->instances ? float_->instances->update_ms : 0;
    return double_->instances ? double_->instances->update_ms : 0;
}

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool) {
    return PreparedScene(scene, settings, pool).render(camera, pool);
}

}  // namespace fh
