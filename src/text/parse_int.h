// A whole number from the text of a flag (or a file's field), in a range;
// anything else is a UsageError naming `what`: "--frame must be in [0, 299],
// got 300".
#pragma once

#include <string>

namespace fh {

int parse_int(const std::string& text, const std::string& what, int min, int max);

}  // namespace fh
