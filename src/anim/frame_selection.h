// Which frames of a movie a run renders, and what their files are called.
// A frame's number and file name depend only on its global index, never on
// the range or shard that selected it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fh {

struct FrameRange {
    int begin = 0;  // [begin, end)
    int end = 0;
};

struct Shard {
    int index = 0;  // K
    int count = 1;  // N: this shard renders frames i with i mod N == K
};

// Frames of [0, frame_count) in the range and the shard, in increasing order.
// A range reaching past the movie is an error (std::invalid_argument).
std::vector<int> select_frames(int frame_count, std::optional<FrameRange> range,
                               std::optional<Shard> shard);

// "A:B" -> FrameRange; "K/N" -> Shard; std::invalid_argument on bad syntax or values.
FrameRange parse_range(const std::string& text);
Shard parse_shard(const std::string& text);

// --shard auto: this task's shard from a cluster scheduler's environment.
//  - Slurm job array: SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT. The
//    index is made 0-based with SLURM_ARRAY_TASK_MIN (--array=1-4 gives
//    shards 0..3) and divided by SLURM_ARRAY_TASK_STEP (--array=0-30:10);
//    the array must be a regular range (MIN, MIN+STEP, ... MAX, COUNT tasks),
//    else shards would miss frames. shards_flag, if given, must equal COUNT.
//  - Kubernetes Indexed Job: JOB_COMPLETION_INDEX, and shards_flag (the Job's
//    completions) as the count; required then.
// Slurm's variables win when both are set. Neither set, a malformed number or
// an index out of range: std::invalid_argument, naming the variable.
// `env` looks a name up (nullptr: not set); the overload without it reads
// this process's environment.
using EnvLookup = std::function<const char*(const char*)>;
Shard shard_from_environment(std::optional<int> shards_flag, const EnvLookup& env);
Shard shard_from_environment(std::optional<int> shards_flag);

// The value of --shard: "auto" (shard_from_environment) or "K/N"
// (parse_shard; shards_flag must then be absent: --shards goes with auto).
Shard parse_shard_option(const std::string& text, std::optional<int> shards_flag);

// frame_0042.png: zero-padded to 4 digits, or more when the movie needs them.
std::string frame_file_name(int frame, int frame_count);

}  // namespace fh
