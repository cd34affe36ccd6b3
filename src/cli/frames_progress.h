// What `firsthit frames` shows while the pipeline runs: the progress line,
// the clean-ups it made, and the words for an interrupted run.
#pragma once

#include <iostream>
#include <optional>
#include <string>

#include "cli/human.h"
#include "cli/progress.h"
#include "pipeline/frame_pipeline.h"

namespace fh {

class FramesProgress : public FramesObserver {
public:
    FramesProgress(std::string folder, bool show, bool show_messages)
        : folder_(std::move(folder)), show_(show), show_messages_(show_messages) {}

    void removed_temporaries(int count) override {
        if (show_messages_)
            std::cerr << "firsthit: removed " << count << " temporary file(s) left by an interrupted run in "
                      << folder_ << "\n";
    }
    void removed_old_frames(int count) override {
        if (show_messages_)
            std::cerr << "firsthit: --clean removed " << plural(count, "old frame") << " in " << folder_ << "\n";
    }
    void starting(int frames) override { progress_.emplace(frames, show_); }
    void frame_done(int) override { progress_->frame_done(); }
    void abandoning(int done, int total) override {
        progress_->finish();
        std::cerr << "firsthit: interrupted after " << done << " of " << total
                  << " frames (frames in flight abandoned); run again with --resume to render the rest\n";
    }
    void finish() {
        if (progress_) progress_->finish();
    }

private:
    std::string folder_;
    bool show_, show_messages_;
    std::optional<Progress> progress_;
};

}  // namespace fh
