// Scene and movie files read as text: regular files of bounded size, UTF-8 without control bytes.
// Checked before any parser sees the text, so a binary or huge file is refused, never misread.
#pragma once

#include <cstddef>
#include <string>

namespace fh {

// Documented limit on input files, checked before any YAML is parsed: 16 MiB,
// 8,000 times the report's scene, or about 110,000 instances written out in
// YAML. The limit is yaml-cpp's memory: it holds ~60 bytes per byte of the
// file (measured: 1.45 MB of instances, 95 MB; 11.6 MB, 690 MB and 8 s), so
// 16 MiB needs about 1 GB. Larger sets of instances go in a placements file
// (yaml/placements.h), read at 1/20 of that. A bigger file is refused, not read.
inline constexpr std::size_t kMaxInputBytes = std::size_t(16) << 20;

// Reads a scene or movie file as text: it must be a regular file (not a
// folder, device or pipe) of at most kMaxInputBytes, and text: UTF-8 without
// control characters other than tab, line feed and carriage return. Anything
// else is an InputError naming the file (and the offending byte's position).
// A larger file the format allows (a placements table) gives its own max_bytes.
std::string read_input_file(const std::string& path, std::size_t max_bytes = kMaxInputBytes);

// The same checks on text already in memory (`file` names it in errors).
void check_input_text(const std::string& file, const std::string& text, std::size_t max_bytes = kMaxInputBytes);

// The length of the valid UTF-8 character at text[i], or 0 when the bytes
// there are not one (overlong forms, surrogates and values past U+10FFFF are
// not), or when it is a C1 control character (U+0080..U+009F, not allowed in
// YAML but for U+0085).
std::size_t utf8_length(const std::string& text, std::size_t i);

}  // namespace fh
