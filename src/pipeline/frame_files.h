// The files a movie's frames go to: FOLDER/PREFIX NUMBER SUFFIX, from
// `frames --out` (a folder, or a pattern with %04d or ####), and the movie
// file beside them (PREFIXmovie.txt: which movie, how many frames, fps and
// size) that scripts/encode.sh reads and that keeps the frames of two
// different movies or sizes from mixing under the same names.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace fh {

struct FrameFiles {
    std::filesystem::path folder;
    std::string prefix = "frame_";
    std::string suffix = ".png";
    int digits = 0;  // zero padding; 0: 4, or more when the movie needs them

    // PREFIX0042SUFFIX for frame 42 of a frame_count-frame movie.
    std::string name(int frame, int frame_count) const;
    std::filesystem::path path(int frame, int frame_count) const { return folder / name(frame, frame_count); }
    // The names as printf and ffmpeg read them: frame_%04d.png.
    std::string pattern(int frame_count) const;
    // The frame number a file name of this pattern stands for, any padding
    // (frame_12345.png, frame_0007.png); -1 for any other name.
    int frame_of(const std::string& file_name) const;
    // PREFIXmovie.txt: frame_movie.txt beside frame_NNNN.png.
    std::filesystem::path movie_file() const { return folder / (prefix + "movie.txt"); }

private:
    int width(int frame_count) const;
};

// `frames --out`'s text: a pattern when its file name holds %0Nd, %d or a run
// of # (the frame number, zero-padded to N or to the run's length), else a
// folder of frame_NNNN.png. UsageError for two numbers, a number in the
// folder part, or a name not ending in .png.
FrameFiles parse_frame_files(const std::string& out);

// What PREFIXmovie.txt says of the frames: `key: value` lines.
struct FramesOrigin {
    std::string movie;  // the movie file, as an absolute path
    int frames = 0;     // the movie's frame count (not only the rendered ones)
    double fps = 0;
    int width = 0, height = 0;
    std::string pattern;  // the file names, as ffmpeg reads them: frame_%04d.png
    // What else decides their pixels -- the camera, the quality settings,
    // the glTF animation and exposure chosen -- so that --resume or another
    // shard never mixes frames rendered differently: "camera persp, 1
    // sample, depth 5, double" (FramesRequest::render).
    std::string render;

    // The movie file's text; two origins are the same when their texts are.
    std::string text() const;
    // "animations/mine.yaml: 24 frames at 12 fps, 160x120"
    std::string describe() const;
};

// Before `frames` writes anything: makes sure files.folder holds no frames
// under these names from another origin, then writes the movie file.
// Another origin is a movie file that differs in any field, a frame past
// the movie's end, or (no movie file) a frame of another size. With `clean`,
// such frames and their movie file are removed first (the count is
// returned); without it, a UsageError says what is there and what to do.
int claim_frame_folder(const FrameFiles& files, const FramesOrigin& origin, bool clean);

// The movie file's fields; nullopt if there is none. InputError if it is
// there but unreadable or malformed.
std::optional<FramesOrigin> read_frames_origin(const std::filesystem::path& movie_file);

}  // namespace fh
