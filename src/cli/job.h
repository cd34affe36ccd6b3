// The flags that pick what to render and how well (render, frames, bench,
// accuracy, view): FILE, --frame, --camera, --resolution, --scale and the
// quality flags, turned into a loaded Job (pipeline/job.h) and its settings.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "pipeline/job.h"
#include "render/settings.h"

namespace fh {

// One positional FILE, --camera, --frame and the size flags: the loaded job
// (its warnings printed to stderr unless --quiet), with the quality flags
// applied to job.movie.settings. movie_camera_note: the command's own words
// after "FILE is a movie (".
Job job_from_args(const Args& args, const char* movie_camera_note = nullptr);

// The same flags as a request, not yet loaded.
JobRequest job_request_from_args(const Args& args);

// --resolution WxH or --scale F (not both); neither: no override.
SizeOverride size_from_args(const Args& args);

// --spp, --depth, --precision, --adaptive, --aa-*, --no-mipmaps and --no-prune on top of
// the file's settings.
void apply_quality_flags(const Args& args, RenderSettings& settings);

// The one positional FILE; UsageError when there is none or more.
const std::string& one_file(const Args& args);

// The job's warnings, one line each on stderr.
void print_warnings(const Job& job);

}  // namespace fh
