// Output files that are whole or absent: written under a temporary name and renamed, the temporaries
// a killed run leaves cleaned up, and output places checked before any rendering. Nothing here is PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fh {

// Writes bytes to path atomically; throws std::runtime_error naming the path.
// The bytes go under a temporary name in the same folder, are flushed to disk
// (fsync) and renamed over the target, so a reader, a killed run or a machine
// that loses power only ever sees a whole file or none.
//
// The temporary is NAME.tmp-HOST-PID-N (N counts the writes of the process).
// It exists only while one encoded file is written, milliseconds; a run
// killed in that moment leaves it behind, and remove_stale_temporaries
// (called by `firsthit frames` on its output folder) cleans it up.
void write_file_atomic(const std::string& path, const std::vector<std::uint8_t>& bytes);

// The temporary name write_file_atomic would use for `path` as write number
// `n` of this process.
std::string temporary_name(const std::string& path, unsigned n);

// Removes the temporaries of write_file_atomic in `dir` that no live process
// is writing: those of this machine whose process has ended (or whose PID is
// this process's, which has not written there yet), and those of any machine
// (a folder shared by a cluster) last modified more than `max_age_seconds`
// ago. Returns how many it removed.
int remove_stale_temporaries(const std::string& dir, double max_age_seconds = 600);

// Bad output locations, found before any rendering: `path` is an existing
// folder, or its folder does not exist or cannot be written. InputError
// naming the path.
void check_output_file(const std::string& path);
// The same for a file written as a stream (raw video), which may also be
// an existing pipe or device that can be opened for writing (a FIFO,
// /dev/null); "-" (standard output) is always good.
void check_stream_output(const std::string& path);
// `dir` cannot be created, is not a folder, or cannot be written: InputError.
// Creates it (and its parents) when missing.
void prepare_output_folder(const std::string& dir);

}  // namespace fh
