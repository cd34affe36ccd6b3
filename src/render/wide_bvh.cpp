#include "render/wide_bvh.h"

#include <algorithm>

namespace fh {

namespace {

double half_area(const BvhNode& n) {
    const double dx = double(n.hi[0]) - n.lo[0], dy = double(n.hi[1]) - n.lo[1], dz = double(n.hi[2]) - n.lo[2];
    return dx * dy + dy * dz + dz * dx;
}

}  // namespace

WideBvh collapse(const Bvh& bvh, const std::vector<std::int32_t>& walk_of) {
    WideBvh wide;
    if (bvh.empty()) return wide;
    if (bvh.nodes[0].leaf()) {
        wide.root_leaf = walk_of[0];
        return wide;
    }
    // Breadth first: each wide node gathers up to eight binary nodes by
    // opening its largest inner child until it is full or only leaves are left.
    struct Todo {
        std::int32_t binary, wide;  // a binary inner node, the wide node it becomes
    };
    std::vector<Todo> todo{{0, 0}};
    wide.nodes.emplace_back();
    for (size_t next = 0; next < todo.size(); ++next) {
        const Todo t = todo[next];
        std::vector<std::int32_t> kids = {bvh.nodes[size_t(t.binary)].first, bvh.nodes[size_t(t.binary)].second};
        while (int(kids.size()) < kWideChildren) {
            int open = -1;
            for (int k = 0; k < int(kids.size()); ++k) {
                const BvhNode& n = bvh.nodes[size_t(kids[size_t(k)])];
                if (!n.leaf() && (open < 0 || half_area(n) > half_area(bvh.nodes[size_t(kids[size_t(open)])]))) open = k;
            }
            if (open < 0) break;
            const BvhNode& n = bvh.nodes[size_t(kids[size_t(open)])];
            kids[size_t(open)] = n.first;
            kids.push_back(n.second);
        }
        WideNode w;
        for (int c = 0; c < kWideChildren; ++c) {
            for (int a = 0; a < 3; ++a) w.lo[a][c] = w.hi[a][c] = std::numeric_limits<float>::quiet_NaN();
            w.child[c] = 0;
        }
        for (size_t c = 0; c < kids.size(); ++c) {
            const BvhNode& n = bvh.nodes[size_t(kids[c])];
            for (int a = 0; a < 3; ++a) {
                w.lo[a][c] = n.lo[a];
                w.hi[a][c] = n.hi[a];
            }
            if (n.leaf()) {
                w.child[c] = ~walk_of[size_t(kids[c])];
            } else {
                w.child[c] = std::int32_t(wide.nodes.size());
                todo.push_back({kids[c], w.child[c]});
                wide.nodes.emplace_back();
            }
        }
        wide.nodes[size_t(t.wide)] = w;
    }
    return wide;
}

}  // namespace fh
