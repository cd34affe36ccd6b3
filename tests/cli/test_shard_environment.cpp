// --shard auto: the shard from a Slurm job array's or a Kubernetes
// Indexed Job's environment.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "cli/cluster_shard.h"

namespace fh {
namespace {

using Env = std::map<std::string, std::string>;

Shard shard(const Env& env, std::optional<int> shards = std::nullopt) {
    return shard_from_environment(shards, [&](const char* name) -> const char* {
        const auto it = env.find(name);
        return it == env.end() ? nullptr : it->second.c_str();
    });
}

// The message of the std::invalid_argument shard() throws ("" if none).
std::string error(const Env& env, std::optional<int> shards = std::nullopt) {
    try {
        shard(env, shards);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

void expect_shard(const Shard& s, int index, int count) {
    EXPECT_EQ(s.index, index);
    EXPECT_EQ(s.count, count);
}

TEST(ShardFromEnvironment, SlurmJobArrayFromZero) {
    // sbatch --array=0-3
    for (int k = 0; k < 4; ++k)
        expect_shard(shard({{"SLURM_ARRAY_TASK_ID", std::to_string(k)},
                            {"SLURM_ARRAY_TASK_COUNT", "4"},
                            {"SLURM_ARRAY_TASK_MIN", "0"},
                            {"SLURM_ARRAY_TASK_MAX", "3"},
                            {"SLURM_ARRAY_TASK_STEP", "1"}}),
                     k, 4);
    // Only the two variables the issue names.
    expect_shard(shard({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}), 2, 3);
}

TEST(ShardFromEnvironment, SlurmIdsAreMadeZeroBasedWithMinAndStep) {
    // --array=1-4: task IDs 1..4 are shards 0..3.
    for (int id = 1; id <= 4; ++id)
        expect_shard(shard({{"SLURM_ARRAY_TASK_ID", std::to_string(id)},
                            {"SLURM_ARRAY_TASK_COUNT", "4"},
                            {"SLURM_ARRAY_TASK_MIN", "1"},
                            {"SLURM_ARRAY_TASK_MAX", "4"}}),
                     id - 1, 4);
    // --array=10-40:10 (Slurm sets STEP): IDs 10, 20, 30, 40 are shards 0..3.
    expect_shard(shard({{"SLURM_ARRAY_TASK_ID", "30"},
                        {"SLURM_ARRAY_TASK_COUNT", "4"},
                        {"SLURM_ARRAY_TASK_MIN", "10"},
                        {"SLURM_ARRAY_TASK_MAX", "40"},
                        {"SLURM_ARRAY_TASK_STEP", "10"}}),
                 2, 4);
    // --shards N agreeing with the array's count is fine.
    expect_shard(shard({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}, 4), 1, 4);
}

TEST(ShardFromEnvironment, SlurmArraysThatWouldMissFramesAreRefused) {
    // --array=1,3,8: Slurm reports MIN=1 MAX=8 COUNT=3; ID - MIN would give
    // shards 0, 2, 7 of 3, and frames i mod 3 == 1 nobody's.
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "3"},
                     {"SLURM_ARRAY_TASK_COUNT", "3"},
                     {"SLURM_ARRAY_TASK_MIN", "1"},
                     {"SLURM_ARRAY_TASK_MAX", "8"},
                     {"SLURM_ARRAY_TASK_STEP", "1"}}),
              "--shard auto: the job array is not a regular range MIN-MAX:STEP (SLURM_ARRAY_TASK_ID=3, "
              "SLURM_ARRAY_TASK_MIN=1, SLURM_ARRAY_TASK_STEP=1, SLURM_ARRAY_TASK_COUNT=3, "
              "SLURM_ARRAY_TASK_MAX=8); submit it as --array=0-2");
    // An ID outside the array, or between its steps.
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}),
              "--shard auto: task 4 is not in the job array (SLURM_ARRAY_TASK_ID=4, SLURM_ARRAY_TASK_MIN=0, "
              "SLURM_ARRAY_TASK_STEP=1, SLURM_ARRAY_TASK_COUNT=4)");
    EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}}),
              "");
    EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "15"},
                     {"SLURM_ARRAY_TASK_COUNT", "4"},
                     {"SLURM_ARRAY_TASK_MIN", "10"},
                     {"SLURM_ARRAY_TASK_STEP", "10"}}),
              "");
    EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_STEP", "0"}}),
              "");
    // A count that disagrees with --shards.
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}, 3),
              "--shards 3 disagrees with the Slurm job array's SLURM_ARRAY_TASK_COUNT=4");
}

TEST(ShardFromEnvironment, SlurmMalformedOrMissingValues) {
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "2"}}),
              "--shard auto: SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not (need a count >= 1)");
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "0"}}),
              "--shard auto: SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is 0 (need a count >= 1)");
    for (const char* bad : {"", "x", "1x", "-1", " 1", "1.5"})
        EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", bad}, {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                  std::string("--shard auto: SLURM_ARRAY_TASK_ID='") + bad + "' is not a whole number >= 0")
            << bad;
    for (const char* big : {"1000000001", "99999999999999999999"})
        EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", big}, {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                  std::string("--shard auto: SLURM_ARRAY_TASK_ID='") + big + "' is more than 1000000000")
            << big;
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "four"}}),
              "--shard auto: SLURM_ARRAY_TASK_COUNT='four' is not a whole number >= 0");
    EXPECT_EQ(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "?"}}),
              "--shard auto: SLURM_ARRAY_TASK_MIN='?' is not a whole number >= 0");
}

TEST(ShardFromEnvironment, KubernetesIndexedJobWithShards) {
    for (int k = 0; k < 5; ++k) expect_shard(shard({{"JOB_COMPLETION_INDEX", std::to_string(k)}}, 5), k, 5);
    EXPECT_EQ(error({{"JOB_COMPLETION_INDEX", "2"}}),
              "--shard auto: JOB_COMPLETION_INDEX=2 (a Kubernetes Indexed Job) needs --shards N, N the Job's "
              "completions");
    EXPECT_EQ(error({{"JOB_COMPLETION_INDEX", "5"}}, 5),
              "--shard auto: JOB_COMPLETION_INDEX=5 is out of range for --shards 5 (need 0 <= index < N)");
    EXPECT_EQ(error({{"JOB_COMPLETION_INDEX", "a"}}, 5),
              "--shard auto: JOB_COMPLETION_INDEX='a' is not a whole number >= 0");
    EXPECT_EQ(error({{"JOB_COMPLETION_INDEX", "0"}}, 0), "--shards must be >= 1, got 0");
}

TEST(ShardFromEnvironment, SlurmWinsOverKubernetes) {
    expect_shard(shard({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "2"}, {"JOB_COMPLETION_INDEX", "0"}}),
                 1, 2);
}

TEST(ShardFromEnvironment, NeitherSetIsAnError) {
    const std::string neither =
        "--shard auto: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor JOB_COMPLETION_INDEX (a Kubernetes "
        "Indexed Job, with --shards N) is set; outside a scheduler use --shard K/N";
    EXPECT_EQ(error({}), neither);
    EXPECT_EQ(error({}, 4), neither);
    // A plain (non-array) Slurm job has no task ID either.
    EXPECT_EQ(error({{"SLURM_JOB_ID", "12"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}), neither);
}

TEST(ShardFromEnvironment, ParseShardOption) {
    expect_shard(parse_shard_option("2/5", std::nullopt), 2, 5);
    EXPECT_THROW(parse_shard_option("2/5", 5), std::invalid_argument);
    EXPECT_THROW(parse_shard_option("auto5", std::nullopt), std::invalid_argument);
}

// The overload without a lookup reads this process's environment. The
// variables are set for the test and put back as they were.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            ::setenv(name_.c_str(), old_->c_str(), 1);
        else
            ::unsetenv(name_.c_str());
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string name_;
    std::optional<std::string> old_;
};

TEST(ShardFromEnvironment, ReadsTheProcessEnvironment) {
    const ScopedEnv id("SLURM_ARRAY_TASK_ID", "3"), count("SLURM_ARRAY_TASK_COUNT", "4"),
        min("SLURM_ARRAY_TASK_MIN", "1"), max("SLURM_ARRAY_TASK_MAX", "4"), step("SLURM_ARRAY_TASK_STEP", nullptr),
        index("JOB_COMPLETION_INDEX", nullptr);
    expect_shard(shard_from_environment(std::nullopt), 2, 4);
    expect_shard(parse_shard_option("auto", std::nullopt), 2, 4);
    {
        const ScopedEnv no_slurm("SLURM_ARRAY_TASK_ID", nullptr), k8s("JOB_COMPLETION_INDEX", "1");
        expect_shard(shard_from_environment(3), 1, 3);
        EXPECT_THROW(shard_from_environment(std::nullopt), std::invalid_argument);
    }
    EXPECT_STREQ(std::getenv("SLURM_ARRAY_TASK_ID"), "3");  // restored
}

}  // namespace
}  // namespace fh
