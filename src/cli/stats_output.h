// `key: value` lines on stdout, the form --stats and bench print.
#pragma once

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "render/render.h"

namespace fh {

inline void print_counts(std::ostream& out, const RayCounts& c) {
    out << "rays.primary: " << c.primary << "\n"
        << "rays.shadow: " << c.shadow << "\n"
        << "rays.reflection: " << c.reflection << "\n"
        << "rays.transmitted: " << c.transmitted << "\n"
        << "rays.total: " << c.total() << "\n"
        << "nonfinite_samples: " << c.nonfinite_samples << "\n";
}

// The effect plan: what is simulated, and what is not and why. One line
// says what was skipped, so it cannot contradict another.
inline void print_plan(std::ostream& out, const EffectPlan& plan) {
    out << "effects: " << plan.effects.names() << "\n"
        << "max_depth: " << plan.max_depth << "\n"
        << "skipped: ";
    for (size_t i = 0; i < plan.skipped.size(); ++i) out << (i ? "; " : "") << plan.skipped[i];
    if (plan.skipped.empty())
        out << (plan.pruned ? "nothing (every effect asked for can change a pixel)"
                            : "nothing (--no-prune: every effect asked for is simulated)");
    out << "\n";
}

// Samples per pixel, and with adaptive anti-aliasing what it did.
inline void print_sampling(std::ostream& out, const RenderSettings& s, const FrameResult& r) {
    out << "samples_per_pixel: " << s.samples_per_pixel << "\n"
        << "adaptive: " << (s.adaptive ? "on" : "off") << "\n";
    if (!s.mipmaps) out << "mipmaps: off\n";
    if (!s.adaptive) return;
    out << "adaptive_threshold: " << s.adaptive_threshold << "\n"
        << "adaptive_samples: " << s.adaptive_samples << "\n"
        << "refined_pixels: " << r.refined_pixels << "\n";
}

}  // namespace fh
