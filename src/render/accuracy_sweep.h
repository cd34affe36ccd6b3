// What each accuracy knob costs (the promise "error next to time"): a
// converged reference, then samples per pixel (uniform and adaptive), glazing
// depth, precision and (where a texture may be seen from afar) mipmaps
// swept, each with its median render time, rays and error. `firsthit
// accuracy` prints the rows as CSV and plots them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/image_compare.h"
#include "render/render.h"

namespace fh {

struct AccuracyOptions {
    int runs = 3;              // timed runs per setting; the median is reported
    int reference_spp = 256;   // samples per pixel of the reference
    int max_spp = 64;          // largest samples per pixel swept
};

struct AccuracyRow {
    std::string knob;  // "reference", "spp", "adaptive", "depth", "precision" or "mipmaps"
    RenderSettings settings;
    double ms = 0;
    std::uint64_t rays = 0;
    size_t refined_pixels = 0;  // adaptive: pixels given more samples
    ImageError error;           // against the reference
    // Depth and precision rows: against a one-sample reference, which
    // isolates their own error from the aliasing of one sample.
    ImageError isolated;
};

struct AccuracyReport {
    std::vector<AccuracyRow> rows;  // the reference first
};

// `started_reference` is told the reference's depth before it is rendered;
// `measured` is called after each row (a progress line).
AccuracyReport sweep_accuracy(const Scene& scene, const Camera& camera, const RenderSettings& base,
                              const AccuracyOptions& options, ThreadPool& pool,
                              const std::function<void(int depth)>& started_reference = {},
                              const std::function<void(int rows)>& measured = {});

}  // namespace fh
