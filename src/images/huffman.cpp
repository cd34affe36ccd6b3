#include "images/huffman.h"

#include <algorithm>
#include <numeric>

namespace fh {

std::vector<std::uint8_t> huffman_lengths(std::span<const std::uint32_t> freq, int max_length) {
    const int n = int(freq.size());
    std::vector<std::uint8_t> lengths(size_t(n), 0);
    std::vector<int> used;  // symbols with a frequency, rarest first
    for (int s = 0; s < n; ++s)
        if (freq[size_t(s)] > 0) used.push_back(s);
    if (used.empty()) return lengths;
    if (n == 1) {  // no second symbol to pair with
        lengths[0] = 1;
        return lengths;
    }
    if (used.size() == 1) used.push_back(used[0] == 0 ? 1 : 0);  // two codes: a complete code
    std::stable_sort(used.begin(), used.end(),
                     [&](int a, int b) { return freq[size_t(a)] < freq[size_t(b)]; });
    const int m = int(used.size());

    // Huffman's tree with two queues: leaves (sorted) and merged nodes
    // (created in ascending weight). Nodes 0..m-1 are the leaves, m.. the merges.
    std::vector<std::uint64_t> weight(size_t(2 * m - 1));
    std::vector<int> parent(size_t(2 * m - 1), -1);
    for (int i = 0; i < m; ++i) weight[size_t(i)] = std::max<std::uint32_t>(freq[size_t(used[size_t(i)])], 1);
    int leaf = 0, merged = m, next = m;
    auto take = [&] {
        const bool from_leaves =
            leaf < m && (merged == next || weight[size_t(leaf)] <= weight[size_t(merged)]);
        return from_leaves ? leaf++ : merged++;
    };
    for (; next < 2 * m - 1; ++next) {
        const int a = take(), b = take();
        weight[size_t(next)] = weight[size_t(a)] + weight[size_t(b)];
        parent[size_t(a)] = parent[size_t(b)] = next;
    }
    // Depths, from the root (the last node) down: a parent always comes later.
    std::vector<int> depth(size_t(2 * m - 1), 0);
    for (int i = 2 * m - 3; i >= 0; --i) depth[size_t(i)] = depth[size_t(parent[size_t(i)])] + 1;

    // How many codes of each length, the too-long ones counted as max_length.
    std::vector<int> count(size_t(max_length) + 1, 0);
    for (int i = 0; i < m; ++i) ++count[size_t(std::min(depth[size_t(i)], max_length))];
    // Clamping raised the Kraft sum (in units of 2^-max_length) above one.
    // Each round takes a code off the deepest level and splits a leaf of the
    // deepest shallower level into two one level down: as many codes as
    // before, and the sum one unit smaller, until the code is complete again.
    long long kraft = 0;
    for (int len = 1; len <= max_length; ++len) kraft += (long long)count[size_t(len)] << (max_length - len);
    while (kraft > (1LL << max_length)) {
        --count[size_t(max_length)];
        for (int len = max_length - 1; len > 0; --len) {
            if (count[size_t(len)] > 0) {
                --count[size_t(len)];
                count[size_t(len) + 1] += 2;
                break;
            }
        }
        --kraft;
    }
    // Lengths to symbols: the shortest to the most frequent (used is rarest first).
    int i = m - 1;
    for (int len = 1; len <= max_length; ++len)
        for (int k = 0; k < count[size_t(len)]; ++k) lengths[size_t(used[size_t(i--)])] = std::uint8_t(len);
    return lengths;
}

std::vector<std::uint16_t> canonical_codes(std::span<const std::uint8_t> lengths) {
    int max_length = 0;
    for (const std::uint8_t l : lengths) max_length = std::max(max_length, int(l));
    std::vector<int> count(size_t(max_length) + 1, 0);
    for (const std::uint8_t l : lengths) ++count[l];
    count[0] = 0;
    std::vector<int> next(size_t(max_length) + 1, 0);
    for (int len = 1, code = 0; len <= max_length; ++len) {
        code = (code + count[size_t(len) - 1]) << 1;
        next[size_t(len)] = code;
    }
    std::vector<std::uint16_t> codes(lengths.size(), 0);
    for (size_t s = 0; s < lengths.size(); ++s) {
        const int len = lengths[s];
        if (len == 0) continue;
        const int code = next[size_t(len)]++;
        int reversed = 0;
        for (int b = 0; b < len; ++b) reversed |= ((code >> b) & 1) << (len - 1 - b);
        codes[s] = std::uint16_t(reversed);
    }
    return codes;
}

}  // namespace fh
