// The movie file (docs/format.md): a scene, one of its
// cameras, the lights switched on, the frame rate and length, camera paths, and
// render settings and effects that override the scene's. Loading is as strict
// as the scene's: every mistake is an fh::InputError with file, line and column.
#pragma once

#include <string>

#include "anim/movie.h"

namespace fh {

// Documented limit: round(fps * seconds) must be between 1 and this (a million
// frames is over nine hours at 30 fps).
inline constexpr int kMaxMovieFrames = 1'000'000;

// Loads a movie and its scene (`scene:` is relative to the movie's folder).
// `camera:` may be left out: the scene's first camera is used. `lights:` left
// out keeps all of the scene's lights. Errors in the scene file are reported
// against the scene file.
Movie load_movie(const std::string& path);

// The same from the movie file's text in memory; `path` names it in errors
// and is where `scene:` is found from (the scene file itself is read from disk).
Movie load_movie_from_string(const std::string& text, const std::string& path);

// True when the file is a YAML map with a `scene` key, i.e. a movie rather than
// a scene. False for anything else: glTF files (a .gltf's JSON has a "scene"
// of its own), and unreadable, too large, binary, too deeply nested or
// unparsable files (loading it as a scene then reports what is wrong).
bool is_movie_file(const std::string& path);

}  // namespace fh
