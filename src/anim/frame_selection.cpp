#include "anim/frame_selection.h"

#include <cerrno>
#include <cstdlib>
#include <stdexcept>

namespace fh {

namespace {
int parse_nonnegative(const std::string& s, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE || v < 0 || v > 1'000'000'000)
        throw std::invalid_argument(what + ": '" + s + "' is not a whole number >= 0");
    return int(v);
}
}  // namespace

FrameRange parse_range(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        throw std::invalid_argument("--range must look like A:B (frames A to B-1), got '" + text + "'");
    FrameRange r{parse_nonnegative(text.substr(0, colon), "--range start"),
                 parse_nonnegative(text.substr(colon + 1), "--range end")};
    if (r.begin >= r.end)
        throw std::invalid_argument("--range " + text + " is empty: A must be less than B");
    return r;
}

Shard parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    if (slash == std::string::npos)
        throw std::invalid_argument("--shard must look like K/N (0 <= K < N), got '" + text + "'");
    Shard s{parse_nonnegative(text.substr(0, slash), "--shard K"),
            parse_nonnegative(text.substr(slash + 1), "--shard N")};
    if (s.count < 1 || s.index >= s.count)
        throw std::invalid_argument("--shard " + text + ": need 0 <= K < N");
    return s;
}

namespace {
// A variable of the environment as a whole number >= 0, or nullopt if unset.
std::optional<long long> env_number(const EnvLookup& env, const char* name) {
    const char* v = env(name);
    if (v == nullptr) return std::nullopt;
    const std::string s = v;
    // Digits only: no sign, no spaces, at most 1e9.
    const bool digits = !s.empty() && s.size() <= 10 &&
                        s.find_first_not_of("0123456789") == std::string::npos;
    const long long n = digits ? std::stoll(s) : -1;
    if (n < 0 || n > 1'000'000'000)
        throw std::invalid_argument(std::string("--shard auto: ") + name + "='" + s +
                                    "' is not a whole number >= 0");
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

std::vector<int> select_frames(int frame_count, std::optional<FrameRange> range,
                               std::optional<Shard> shard) {
    FrameRange r = range.value_or(FrameRange{0, frame_count});
    if (r.end > frame_count)
        throw std::invalid_argument("--range " + std::to_string(r.begin) + ":" +
                                    std::to_string(r.end) + " reaches past the movie's " +
                                    std::to_string(frame_count) + " frames");
    const Shard s = shard.value_or(Shard{0, 1});
    std::vector<int> frames;
    for (int i = r.begin; i < r.end; ++i)
        if (i % s.count == s.index) frames.push_back(i);
    return frames;
}

std::string frame_file_name(int frame, int frame_count) {
    size_t digits = std::to_string(frame_count > 0 ? frame_count - 1 : 0).size();
    if (digits < 4) digits = 4;
    std::string n = std::to_string(frame);
    if (n.size() < digits) n.insert(0, digits - n.size(), '0');
    return "frame_" + n + ".png";
}

}  // namespace fh
