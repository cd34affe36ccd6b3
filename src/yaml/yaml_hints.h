// Plain-words hints for YAML syntax errors: yaml-cpp says "end of map not
// found" where the cause is a tab, an unclosed quote or bracket, a missing
// colon or space, or a wrong indentation a few lines up. Only the standard
// library: the text is looked at as lines, not parsed again.
#pragma once

#include <string>

namespace fh {

// A hint for yaml-cpp's error `message` ("end of map not found") at `line`,
// `column` (1-based, in bytes as yaml-cpp counts; 0 = unknown) of `text`, or
// "" when none of the common mistakes is found. The first that applies:
//   "line 9 is indented with a tab; YAML indents with spaces only"
//   "the quote opened at line 18, column 60 is not closed on its line"
//   "the '[' at line 18, column 28 is closed by '}' at line 18, column 63"
//   "the ']' at line 3, column 5 closes nothing"
//   "the '{' at line 18, column 5 is never closed"
// and, for the block-structure messages only (end of map/sequence not
// found, illegal block entry, illegal map key or value):
//   "line 6: put a space after the colon in 'materials:x' ('materials: x')"
//   "line 6: 'materials' has no colon; write 'materials:'"
//   "line 2: 'fps 3' has no colon; write 'fps: 3'"
//   "line 9 is indented by 3 spaces and line 7 by 2: keys of one map, and
//    items of one list, start in the same column"
//   "check the indentation of line 9: keys of one map, and ..." (the same end)
// Columns in hints count characters. Meant to be appended as " (HINT)".
std::string yaml_hint(const std::string& text, int line, int column, const std::string& message);

}  // namespace fh
