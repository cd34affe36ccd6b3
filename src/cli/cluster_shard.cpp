#include "cli/cluster_shard.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace fh {

namespace {
// A variable of the environment as a whole number >= 0, or nullopt if unset.
std::optional<long long> env_number(const EnvLookup& env, const char* name) {
    const char* v = env(name);
    if (v == nullptr) return std::nullopt;
    const std::string s = v;
    long long n = 0;
    const std::string problem = frame_number_problem(s, n);  // no sign, no spaces
    if (!problem.empty()) throw std::invalid_argument(std::string("--shard auto: ") + name + "='" + s + "' " + problem);
    return n;
}

std::string assignment(const char* name, long long value) {
    return std::string(name) + "=" + std::to_string(value);
}

Shard shard_from_slurm(long long id, std::optional<int> shards_flag, const EnvLookup& env) {
    const auto count = env_number(env, "SLURM_ARRAY_TASK_COUNT");
    if (!count || *count < 1)
        throw std::invalid_argument(
            "--shard auto: SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is " +
            (count ? std::to_string(*count) : std::string("not")) + " (need a count >= 1)");
    const long long min = env_number(env, "SLURM_ARRAY_TASK_MIN").value_or(0);
    const long long step = env_number(env, "SLURM_ARRAY_TASK_STEP").value_or(1);
    const std::string array = assignment("SLURM_ARRAY_TASK_ID", id) + ", " +
                              assignment("SLURM_ARRAY_TASK_MIN", min) + ", " +
                              assignment("SLURM_ARRAY_TASK_STEP", step) + ", " +
                              assignment("SLURM_ARRAY_TASK_COUNT", *count);
    if (step < 1) throw std::invalid_argument("--shard auto: SLURM_ARRAY_TASK_STEP must be >= 1 (" + array + ")");
    if (const auto max = env_number(env, "SLURM_ARRAY_TASK_MAX"); max && *max != min + (*count - 1) * step)
        throw std::invalid_argument("--shard auto: the job array is not a regular range MIN-MAX:STEP (" + array +
                                    ", " + assignment("SLURM_ARRAY_TASK_MAX", *max) +
                                    "); submit it as --array=0-" + std::to_string(*count - 1));
    if (id < min || (id - min) % step != 0 || (id - min) / step >= *count)
        throw std::invalid_argument("--shard auto: task " + std::to_string(id) + " is not in the job array (" +
                                    array + ")");
    if (shards_flag && *shards_flag != *count)
        throw std::invalid_argument("--shards " + std::to_string(*shards_flag) +
                                    " disagrees with the Slurm job array's " + assignment("SLURM_ARRAY_TASK_COUNT", *count));
    return Shard{int((id - min) / step), int(*count)};
}
}  // namespace

Shard shard_from_environment(std::optional<int> shards_flag, const EnvLookup& env) {
    if (shards_flag && *shards_flag < 1)
        throw std::invalid_argument("--shards must be >= 1, got " + std::to_string(*shards_flag));
    if (const auto id = env_number(env, "SLURM_ARRAY_TASK_ID")) return shard_from_slurm(*id, shards_flag, env);
    if (const auto index = env_number(env, "JOB_COMPLETION_INDEX")) {
        if (!shards_flag)
            throw std::invalid_argument("--shard auto: " + assignment("JOB_COMPLETION_INDEX", *index) +
                                        " (a Kubernetes Indexed Job) needs --shards N, N the Job's completions");
        if (*index >= *shards_flag)
            throw std::invalid_argument("--shard auto: " + assignment("JOB_COMPLETION_INDEX", *index) +
                                        " is out of range for --shards " + std::to_string(*shards_flag) +
                                        " (need 0 <= index < N)");
        return Shard{int(*index), *shards_flag};
    }
    throw std::invalid_argument(
        "--shard auto: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor JOB_COMPLETION_INDEX (a Kubernetes "
        "Indexed Job, with --shards N) is set; outside a scheduler use --shard K/N");
}

Shard shard_from_environment(std::optional<int> shards_flag) {
    return shard_from_environment(shards_flag, [](const char* name) { return std::getenv(name); });
}

Shard parse_shard_option(const std::string& text, std::optional<int> shards_flag) {
    if (text == "auto") return shard_from_environment(shards_flag);
    if (shards_flag)
        throw std::invalid_argument("--shards N goes with --shard auto (--shard K/N names its own count)");
    return parse_shard(text);
}

}  // namespace fh
