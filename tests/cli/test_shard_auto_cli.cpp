// firsthit frames --shard auto: the shard from a Slurm job array's
// or a Kubernetes Indexed Job's environment gives the same frames, byte for
// byte, as one run; a missing or bad environment is a usage error.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli/small_movie.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// firsthit frames with exactly the scheduler variables `env` (VAR=value
// words), whatever the environment ctest runs in.
CommandResult frames_with_env(const fs::path& dir, const std::string& env, const std::string& args) {
    return run_shell(
        "env -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_COUNT -u SLURM_ARRAY_TASK_MIN -u SLURM_ARRAY_TASK_MAX "
        "-u SLURM_ARRAY_TASK_STEP -u JOB_COMPLETION_INDEX " +
        env + " " + FIRSTHIT_BINARY + " frames " + (dir / "tiny.yaml").string() + " --quiet --threads 1 " + args);
}

TEST(ShardAutoCli, SlurmArrayFromOneAndKubernetesGiveTheBytesOfOneRun) {
    const fs::path dir = tiny_movie("shard_auto");
    ASSERT_EQ(run_firsthit("frames " + (dir / "tiny.yaml").string() + " --quiet --out " + (dir / "full").string())
                  .status,
              0);
    const auto full = frames_in(dir / "full");
    ASSERT_EQ(full.size(), 12u);

    // sbatch --array=1-3: task IDs 1, 2, 3 render shards 0, 1, 2 of 3.
    for (int id = 1; id <= 3; ++id) {
        const fs::path out = dir / ("task" + std::to_string(id));
        const auto r = frames_with_env(dir,
                                       "SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                                           " SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1 "
                                           "SLURM_ARRAY_TASK_MAX=3 SLURM_ARRAY_TASK_STEP=1",
                                       "--shard auto --out " + out.string());
        ASSERT_EQ(r.status, 0) << r.err;
        std::vector<std::string> want;
        for (int i = id - 1; i < 12; i += 3) want.push_back(full[size_t(i)]);
        EXPECT_EQ(frames_in(out), want) << "task " << id;
        for (const auto& name : frames_in(out))
            EXPECT_EQ(slurp(out / name), slurp(dir / "full" / name)) << name;
    }

    // A Kubernetes Indexed Job with completions: 4, all into one folder.
    for (int k = 0; k < 4; ++k) {
        const auto r = frames_with_env(dir, "JOB_COMPLETION_INDEX=" + std::to_string(k),
                                       "--shard auto --shards 4 --out " + (dir / "k8s").string());
        ASSERT_EQ(r.status, 0) << r.err;
    }
    ASSERT_EQ(frames_in(dir / "k8s"), full);
    for (const auto& name : full) EXPECT_EQ(slurp(dir / "k8s" / name), slurp(dir / "full" / name)) << name;
}

TEST(ShardAutoCli, MissingOrBadEnvironmentIsAUsageError) {
    const fs::path dir = tiny_movie("shard_auto_bad");
    const std::string out = "--out " + (dir / "f").string();
    const auto neither = frames_with_env(dir, "", "--shard auto " + out);
    EXPECT_EQ(neither.status, 2);
    EXPECT_EQ(neither.err,
              "firsthit: error: --shard auto: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor "
              "JOB_COMPLETION_INDEX (a Kubernetes Indexed Job, with --shards N) is set; outside a scheduler use "
              "--shard K/N\n");

    const std::vector<std::pair<std::string, std::string>> cases{
        {"SLURM_ARRAY_TASK_ID=2", "--shard auto"},
        {"SLURM_ARRAY_TASK_ID=x SLURM_ARRAY_TASK_COUNT=4", "--shard auto"},
        {"SLURM_ARRAY_TASK_ID=4 SLURM_ARRAY_TASK_COUNT=4", "--shard auto"},
        {"SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=4", "--shard auto --shards 3"},
        {"JOB_COMPLETION_INDEX=1", "--shard auto"},
        {"JOB_COMPLETION_INDEX=4", "--shard auto --shards 4"},
        {"JOB_COMPLETION_INDEX=1", "--shard auto --shards 0"},
        {"JOB_COMPLETION_INDEX=1", "--shards 4"},
        {"JOB_COMPLETION_INDEX=1", "--shard 1/4 --shards 4"},
    };
    for (const auto& [env, args] : cases) {
        const auto r = frames_with_env(dir, env, args + " " + out);
        EXPECT_EQ(r.status, 2) << env << " " << args;
        EXPECT_EQ(r.err.rfind("firsthit: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_TRUE(frames_in(dir / "f").empty());  // nothing rendered
}

}  // namespace
}  // namespace fh::test
