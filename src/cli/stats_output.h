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
        << "rays.total: " << c.total() << "\n"
        << "nonfinite_samples: " << c.nonfinite_samples << "\n";
}

// The effect plan: what is simulated, and why the rest is not.
inline void print_plan(std::ostream& out, const EffectPlan& plan) {
    out << "effects: " << plan.effects.names() << "\n"
        << "max_depth: " << plan.max_depth << "\n"
        << "pruned: " << (plan.pruned ? "yes" : "no (--no-prune)") << "\n"
        << "skipped: ";
    for (size_t i = 0; i < plan.skipped.size(); ++i) out << (i ? "; " : "") << plan.skipped[i];
    out << (plan.skipped.empty() ? "nothing\n" : "\n");
}

}  // namespace fh
