// Small movies for the CLI tests: a copy of the report's scene at a small
// size and an orbit like Movie 1's, one second long.
#pragma once

#include <algorithm>
#include <regex>
#include <string>
#include <vector>

#include "cli/run_command.h"

namespace fh::test {

// DIR/scene.yaml (width x height) and DIR/MOVIE_FILE (fps frames, Movie 1's
// lights and orbit, then `extra` YAML lines). Returns DIR, a fresh folder.
inline std::filesystem::path small_movie(const std::string& name, int width, int height, int fps,
                                         const std::string& movie_file, const std::string& extra = "") {
    const std::filesystem::path dir = fresh_dir(name);
    std::string scene = slurp(source_path("animations/scene.yaml"));
    scene = std::regex_replace(scene, std::regex("width: 800"), "width: " + std::to_string(width));
    scene = std::regex_replace(scene, std::regex("height: 800"), "height: " + std::to_string(height));
    std::ofstream(dir / "scene.yaml") << scene;
    std::ofstream(dir / movie_file) << "scene: scene.yaml\ncamera: perspective\n"
                                       "lights: [ambient, spot]\nfps: "
                                    << fps
                                    << "\nseconds: 1\n"
                                       "animate:\n  view_point:\n    orbit: {center: [-10, -10, 16], "
                                       "sin: [20, 0, 0], cos: [0, 0, 15]}\n"
                                       "  look_at: {toward: [0, 0, 0]}\n"
                                    << extra;
    return dir;
}

// DIR/tiny.yaml: a 64x64 copy of the report's scene and a one-second orbit
// of it at `fps` frames a second.
inline std::filesystem::path tiny_movie(const std::string& name, int fps = 12) {
    return small_movie(name, 64, 64, fps, "tiny.yaml");
}

// The names in a folder, sorted; none if it does not exist.
inline std::vector<std::string> files_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    if (std::filesystem::is_directory(dir))
        for (const auto& e : std::filesystem::directory_iterator(dir))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The frame files in a folder `firsthit frames` wrote: its names but the
// movie file beside them (frame_movie.txt), sorted.
inline std::vector<std::string> frames_in(const std::filesystem::path& dir) {
    std::vector<std::string> names = files_in(dir);
    std::erase_if(names, [](const std::string& n) { return n.ends_with("movie.txt"); });
    return names;
}

}  // namespace fh::test
