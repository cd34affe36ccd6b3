// Edit distance and the "did you mean" suggestion built on it: plain strings, shared by the
// command line and the scene and movie loaders.
#include "text/closest_match.h"

#include <algorithm>
#include <climits>
#include <cstddef>

namespace fh {

int edit_distance(const std::string& a, const std::string& b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= n; ++i) {
        for (std::size_t j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            // A swap of two neighbours ("cmaera") is one typo, not two.
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[n][m];
}

std::string closest_match(const std::string& word, const std::vector<std::string>& options) {
    std::string best;
    int best_distance = INT_MAX;
    // The distance is at least the difference in length: long words (a name
    // may be a megabyte) are never compared at quadratic cost.
    if (word.size() > 64) return best;
    for (const std::string& option : options) {
        if (option.size() > word.size() + 2 || word.size() > option.size() + 2) continue;
        const int dist = edit_distance(word, option);
        // At most 2 edits, and not more than half the word: "u" may be "up",
        // but "x" is not "up".
        if (dist <= 2 && dist <= static_cast<int>(option.size()) / 2 && dist < best_distance) {
            best = option;
            best_distance = dist;
        }
    }
    return best;
}

std::string name_hint(const std::string& word, const std::vector<std::string>& options, const std::string& what) {
    if (const std::string near = closest_match(word, options); !near.empty()) return " (did you mean '" + near + "'?)";
    if (options.empty()) return "";
    std::string list;
    for (size_t i = 0; i < options.size() && i < 8; ++i) list += (i ? ", '" : "'") + options[i] + "'";
    return " (" + what + ": " + list + (options.size() > 8 ? ", ..." : "") + ")";
}

}  // namespace fh
