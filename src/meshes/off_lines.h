// An OFF file checked as Debian's assimp 5.2.5 will read it, before it does
// (OFFImporter::InternReadFile over TextFileToBuffer). Its reader allocates
// whatever the header's counts say (400 million vertices in a 200-byte file:
// 4.7 GB), copies each line into a stack buffer of 4,096 bytes and ends the
// copy one byte past it when a line fills it, and takes a face line of no
// vertices, or of more than 9, by counting its faces down without end, so
// that the validator reads past the face array. So the whole file is read
// here as it will read it -- a UTF-8 byte order mark dropped, the header's
// tokens, comment lines and quirks ("OFF" glued to the counts, counts in 32
// bits that wrap), then its lines -- and each of those is refused with its
// reason. (A header that hid its counts behind a byte order mark or 64 KiB of
// comments got past an earlier check of the file's head only: 11 GB
// allocated for a 60-byte file.)
#pragma once

#include <string>

namespace fh {

// InputError(path, ...) for counts larger than the file can hold, a line of
// 4,096 bytes or more, a face of 0 or more than 9 vertices, or bytes assimp
// takes for a UTF-32 byte order mark.
void check_off_file(const std::string& path);

}  // namespace fh
