#include "cli/frames_request.h"

#include <filesystem>
#include <optional>

#include "anim/frame_selection.h"
#include "cli/cluster_shard.h"
#include "files/atomic_file.h"
#include "text/input_error.h"
#include "text/parse_int.h"

namespace fh {

std::vector<int> selected_frames(const Args& args, int n) {
    // --shards N: the count for --shard auto in a Kubernetes Indexed Job.
    const auto shards = args.has("--shards") ? std::optional(args.integer("--shards", 1, 1, 1'000'000)) : std::nullopt;
    if (shards && !args.has("--shard")) throw UsageError("--shards N goes with --shard auto");
    try {
        const auto range = args.value("--range");
        const auto shard_text = args.value("--shard");
        const auto shard = shard_text ? std::optional(parse_shard_option(*shard_text, shards)) : std::nullopt;
        if (const auto frame = args.value("--frame")) {
            if (range) throw UsageError("--frame N is --range N-N: give one of them");
            const int i = parse_int(*frame, "--frame", 0, n - 1);
            return select_frames(n, FrameRange{i, i + 1}, shard);
        }
        return select_frames(n, range ? std::optional(parse_range(*range)) : std::nullopt, shard);
    } catch (const std::invalid_argument& e) {
        const auto range = args.value("--range");
        const std::string what = e.what();
        throw UsageError(range && what.rfind("--range", 0) != 0 ? "--range " + *range + ": " + what : what);
    }
}

namespace {

// --raw-video FILE and --raw-pix-fmt into the request.
void read_raw_video(const Args& args, FramesRequest& request) {
    const auto raw = args.value("--raw-video");
    if (!raw) {
        if (args.has("--raw-pix-fmt")) throw UsageError("--raw-pix-fmt goes with --raw-video");
        return;
    }
    if (args.has("--shard") || args.has("--resume"))
        throw UsageError("--raw-video streams whole runs of frames: not with --shard or --resume");
    if (*raw == "-" && args.has("--stats"))
        throw UsageError("--raw-video - writes frames to standard output: not with --stats");
    try {
        if (const auto name = args.value("--raw-pix-fmt")) request.raw_pixel_format = parse_raw_pixel_format(*name);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--raw-pix-fmt: ") + e.what());
    }
    check_stream_output(*raw);  // before --out's folder is made
    request.raw_video = *raw;
}

}  // namespace

FramesRequest frames_request(const Args& args, const std::string& file, std::vector<int> frames) {
    FramesRequest request;
    request.frames = std::move(frames);
    request.threads = args.integer("--threads", 0, 0, 1024);
    const std::filesystem::path fallback = std::filesystem::path("output") / std::filesystem::path(file).stem();
    request.files = parse_frame_files(args.value("--out").value_or(fallback.string()));
    request.movie_file = file;
    request.resume = args.has("--resume");
    request.clean = args.has("--clean");
    if (request.clean && request.resume) throw UsageError("--clean removes the frames --resume would keep: give one");
    if (request.clean && args.has("--shard"))
        throw UsageError("--clean with --shard would remove the frames other shards render: clean once, before");
    read_raw_video(args, request);
    return request;
}

}  // namespace fh
