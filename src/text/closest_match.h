// "Did you mean" hints for misspelt names, shared by the command line and the scene and movie
// loaders. Plain strings only, so the command line does not pull in the YAML reader for them.
#pragma once

#include <string>
#include <vector>

namespace fh {

// Optimal-string-alignment edit distance, for "did you mean" hints.
int edit_distance(const std::string& a, const std::string& b);

// The option closest to `word`, or "" when none is close enough to suggest.
std::string closest_match(const std::string& word, const std::vector<std::string>& options);

// What to append to "no camera 'x'": " (did you mean 'y'?)" when an option
// is close, else " (its cameras: 'a', 'b', 'c')" -- `what` names them -- listing
// the first eight; "" when there are none.
std::string name_hint(const std::string& word, const std::vector<std::string>& options, const std::string& what);

}  // namespace fh
