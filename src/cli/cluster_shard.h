// `--shard auto` and `--shard K/N`: which shard of a movie this task renders,
// from the flag or from a cluster scheduler's environment (Slurm job arrays,
// Kubernetes Indexed Jobs). Command-line concerns, kept out of the library.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "anim/frame_selection.h"

namespace fh {

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

}  // namespace fh
