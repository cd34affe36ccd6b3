#include "render/accuracy_sweep.h"

#include <algorithm>

namespace fh {

AccuracyReport sweep_accuracy(const Scene& scene, const Camera& camera, const RenderSettings& base_settings,
                              const AccuracyOptions& options, ThreadPool& pool,
                              const std::function<void(int depth)>& started_reference,
                              const std::function<void(int rows)>& measured) {
    auto render = [&](const RenderSettings& s) { return render_frame(scene, camera, s, &pool); };
    // The reference: deep enough that one more level of glazing changes nothing.
    RenderSettings ref = base_settings;
    ref.precision = Precision::float64;
    ref.adaptive = false;
    ref.samples_per_pixel = 1;
    ref.max_depth = 16;
    for (; ref.max_depth < Limits::max_depth; ref.max_depth *= 2) {
        RenderSettings deeper = ref;
        deeper.max_depth = std::min(Limits::max_depth, ref.max_depth * 2);
        if (render(ref).image.rgb == render(deeper).image.rgb) break;
    }
    // Depth and precision are also measured against this one sample
    // reference, which isolates their own error from the aliasing of one sample.
    const FrameResult one_sample = render(ref);
    ref.samples_per_pixel = options.reference_spp;
    if (started_reference) started_reference(ref.max_depth);
    const FrameResult reference = render(ref);

    AccuracyReport report;
    std::vector<AccuracyRow>& rows = report.rows;
    const ImageError exact = compare_images(reference.image, reference.image);
    rows.push_back({"reference", ref, reference.render_ms, reference.counts.total(), 0, exact, exact});
    auto measure = [&](const std::string& name, const RenderSettings& s) {
        std::vector<double> ms;
        FrameResult r;
        for (int i = 0; i < options.runs; ++i) {
            r = render(s);
            ms.push_back(r.render_ms);
        }
        const ImageError error = compare_images(r.image, reference.image);
        const bool sampling = name == "spp" || name == "adaptive" || name == "mipmaps";
        rows.push_back({name, s, median(ms), r.counts.total(), r.refined_pixels, error,
                        sampling ? error : compare_images(r.image, one_sample.image)});
        if (measured) measured(int(rows.size()) - 1);
    };
    RenderSettings base = base_settings;
    base.adaptive = false;
    base.precision = Precision::float64;
    base.samples_per_pixel = 1;
    for (int spp = 1; spp <= options.max_spp; spp *= 2) {
        RenderSettings s = base;
        s.samples_per_pixel = spp;
        measure("spp", s);
    }
    for (int spp = 2; spp <= options.max_spp; spp *= 2) {
        RenderSettings s = base;
        s.adaptive = true;
        s.adaptive_samples = spp;
        measure("adaptive", s);
    }
    for (int depth = 0; depth <= 8; ++depth) {
        RenderSettings s = base;
        s.max_depth = depth;
        measure("depth", s);
    }
    for (Precision p : {Precision::float32, Precision::float64}) {
        RenderSettings s = base;
        s.precision = p;
        measure("precision", s);
    }
    // Texture filtering, where a texture may be seen from afar: read as
    // magnified, then from its mipmaps over each ray's footprint.
    if (std::any_of(scene.textures.begin(), scene.textures.end(), [](const Texture& t) { return t.minifies(); }))
        for (const bool mipmaps : {false, true}) {
            RenderSettings s = base;
            s.mipmaps = mipmaps;
            measure("mipmaps", s);
        }
    return report;
}

}  // namespace fh
