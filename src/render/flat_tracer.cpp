// The tracer over flattened scenes (render/flat_scene.h), in the precision
// the settings ask for: compiled once per x86-64 level (render/levels.h).
#include <type_traits>

#include "render/flat_scene.h"
#include "render/prepared_tracer.h"

namespace fh {

namespace {

class FlatTracer final : public PreparedTracer {
public:
    FlatTracer(const Scene& scene, const RenderSettings& settings, ThreadPool* pool) : settings_(settings) {
        const EffectPlan plan = plan_effects(scene, settings);
        if (settings.precision == Precision::float32)
            float_ = std::make_unique<FlatScene<float>>(FlatScene<float>::build(scene, plan, pool));
        else
            double_ = std::make_unique<FlatScene<double>>(FlatScene<double>::build(scene, plan, pool));
    }

    std::unique_ptr<PreparedTracer> for_frame(const Scene& frame, ShapeChanges moved, ThreadPool* pool) const override {
        auto p = std::unique_ptr<FlatTracer>(new FlatTracer());
        p->settings_ = settings_;
        const EffectPlan plan = plan_effects(frame, settings_);
        auto next = [&](const auto& flat) {
            using Flat = std::decay_t<decltype(*flat)>;
            auto geometry = flat->geometry;
            if (moved.world)
                geometry = std::make_shared<const typename decltype(geometry)::element_type>(geometry->refit(frame, pool));
            auto instances = flat->instances;
            using Instances = std::remove_const_t<typename decltype(instances)::element_type>;
            if (moved.instances && instances) instances = Instances::moved(instances, frame, pool);
            return std::make_unique<Flat>(Flat::build(frame, plan, std::move(geometry), std::move(instances)));
        };
        if (float_) p->float_ = next(float_);
        else p->double_ = next(double_);
        return p;
    }

    FrameResult render(const Camera& camera, ThreadPool* pool, const RenderSettings& sampling) const override {
        if (float_) return render_frame_as<float>(*float_, camera, sampling, pool);
        return render_frame_as<double>(*double_, camera, sampling, pool);
    }

    const EffectPlan& plan() const override { return float_ ? float_->plan : double_->plan; }
    double bvh_build_ms() const override {
        return float_ ? float_->geometry->bvh.build_ms : double_->geometry->bvh.build_ms;
    }
    int bvh_nodes() const override {
        return int(float_ ? float_->geometry->bvh.nodes.size() : double_->geometry->bvh.nodes.size());
    }
    std::size_t instances() const override {
        if (float_) return float_->instances ? float_->instances->instances.size() : 0;
        return double_->instances ? double_->instances->instances.size() : 0;
    }

private:
    FlatTracer() = default;
    RenderSettings settings_;  // what the plan of each frame is worked out for
    std::unique_ptr<FlatScene<float>> float_;
    std::unique_ptr<FlatScene<double>> double_;
};

}  // namespace

std::unique_ptr<PreparedTracer> make_flat_tracer(const Scene& scene, const RenderSettings& settings,
                                                 ThreadPool* pool) {
    return std::make_unique<FlatTracer>(scene, settings, pool);
}

}  // namespace fh
