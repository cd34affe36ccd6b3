// OBJ line statements checked as Debian's assimp 5.2.5 will read them,
// before it does. Its importer counts a line statement of n vertices as
// 2 (n - 1) mesh vertices but writes n + max(n - 2, 0) of them: for a line
// of one vertex it writes one more than it counted, and a later line's
// copied vertex lands past the end of the array (heap corruption: a 54-byte
// file aborts the process in glibc's malloc; fuzzing found it, and assimp
// 5.3.0 fixed it). firsthit draws no lines, so such a file is refused.
// So is a vertical tab in a face, line or point statement: getFace reads
// each index by atoi, which skips the tab and the line's end after it and
// reads on, past the end of assimp's line buffer when the statement fills
// it. And in a file over 16 MiB, a "\" before a line end where the line
// reader would look past its 16 MiB cache for the next '\n' (assimp reads
// the file in blocks of that size; no fix upstream).
//
// A statement is split into lines as IOStreamBuffer::getNextDataLine does
// ("\" before a line end joins the next line) and read as
// ObjFileParser::getFace reads it: each value by atoi, the step past it by
// its digits. A vertex of more than three indices ("1/2/3/4") makes getFace
// skip to the next line end -- past the statement's own, into what
// assimp's line buffer holds from earlier lines, and past the buffer's end
// when the statement fills it (a file of one line; fixed in 5.3.0): a face,
// line or point statement with one is refused too.
#pragma once

#include <string>

namespace fh {

// InputError(path, line, 1, ...) for the first line statement above.
// Returns whether every vertex statement gives a colour (`v x y z r g b`:
// six numbers, which assimp reads as a position and a colour). assimp gives
// the k-th colour it read to the k-th vertex, so a file that colours only
// some of its vertices has its colours on the wrong ones: not drawn.
bool check_obj_lines(const std::string& path);

}  // namespace fh
