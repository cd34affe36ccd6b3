// The flags that pick what to render and how well (render, bench, accuracy,
// view): FILE, --frame, --camera and the quality flags, turned into a loaded
// Job (pipeline/job.h) and its settings.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "pipeline/job.h"
#include "render/settings.h"

namespace fh {

// The flags job_from_args reads.
std::vector<FlagSpec> job_flags();

// One positional FILE, --camera and --frame: the loaded job (its warnings
// printed to stderr), with the quality flags applied to job.movie.settings.
// movie_camera_note: the command's own words after "FILE is a movie (".
Job job_from_args(const Args& args, const char* movie_camera_note = nullptr);

// --spp, --depth, --precision, --adaptive, --aa-* and --no-prune on top of
// the file's settings.
void apply_quality_flags(const Args& args, RenderSettings& settings);

// The one positional FILE; UsageError when there is none or more.
const std::string& one_file(const Args& args);

// The job's warnings, one line each on stderr.
void print_warnings(const Job& job);

}  // namespace fh
