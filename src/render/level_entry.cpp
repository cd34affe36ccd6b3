// One level's way into its copy of the tracer (render/levels.h): compiled
// with that level's -march and FIRSTHIT_LEVEL_ENTRY naming it, linked with
// the tracer's objects into one relocatable object whose every other
// symbol is then made local (CMakeLists.txt, firsthit_level), so the
// copies of the three levels never meet.
#include "render/prepared_tracer.h"

#ifndef FIRSTHIT_LEVEL_ENTRY
#error "FIRSTHIT_LEVEL_ENTRY: the entry's name (firsthit_tracer_v2, _v3 or _v4)"
#endif

extern "C" fh::PreparedTracer* FIRSTHIT_LEVEL_ENTRY(const fh::Scene& scene, const fh::RenderSettings& settings,
                                                   fh::ThreadPool* pool) {
    return fh::make_flat_tracer(scene, settings, pool).release();
}
