// `firsthit frames`'s flags as a request to the frame pipeline: which frames
// (--frame, --range, --shard), where they go (--out), and how (--resume,
// --clean, --raw-video, --threads). Combinations that contradict each other
// are UsageError.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "pipeline/frame_pipeline.h"

namespace fh {

// --frame, --range and --shard (or --shard auto) as the frames of an
// n-frame movie, increasing.
std::vector<int> selected_frames(const Args& args, int n);

// The rest of the request around those frames; file: the movie's.
FramesRequest frames_request(const Args& args, const std::string& file, std::vector<int> frames);

}  // namespace fh
