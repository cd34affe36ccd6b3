// The sampler's strata and determinism; the thread pool runs every task once.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <vector>

#include "render/sampler.h"
#include "render/thread_pool.h"

namespace fh {
namespace {

TEST(Sampler, StrataAreAsSquareAsTheCountAllows) {
    EXPECT_EQ(strata_for(1).nx, 1);
    EXPECT_EQ(strata_for(4).nx, 2);
    EXPECT_EQ(strata_for(4).ny, 2);
    EXPECT_EQ(strata_for(8).nx, 4);
    EXPECT_EQ(strata_for(8).ny, 2);
    EXPECT_EQ(strata_for(7).nx, 7);
    EXPECT_EQ(strata_for(7).ny, 1);
}

TEST(Sampler, OneSampleIsThePixelCentre) {
    const auto o = sample_offset(13, 7, 0, strata_for(1));
    EXPECT_EQ(o.x, 0.5);
    EXPECT_EQ(o.y, 0.5);
}

TEST(Sampler, EachStratumGetsExactlyOneSample) {
    for (int n : {2, 4, 8, 16, 64}) {
        const StrataGrid g = strata_for(n);
        std::set<std::pair<int, int>> cells;
        for (int s = 0; s < n; ++s) {
            const auto o = sample_offset(321, 123, s, g);
            ASSERT_GE(o.x, 0);
            ASSERT_LT(o.x, 1);
            cells.insert({int(o.x * g.nx), int(o.y * g.ny)});
        }
        EXPECT_EQ(int(cells.size()), n) << n << " samples";
    }
}

TEST(Sampler, EveryNthOfThePixelGetsOneSampleEachWay) {
    // Multi-jittered: the n samples' x fall in n different n-ths of the
    // pixel, and so do their y -- for 4 samples, plain jitter in 2 x 2
    // strata lets both samples of a row of strata fall in one quarter of
    // the pixel's height.
    for (int n : {2, 4, 7, 8, 16, 64, 256}) {
        const StrataGrid g = strata_for(n);
        for (int p = 0; p < 50; ++p) {
            std::set<int> xs, ys;
            for (int s = 0; s < n; ++s) {
                const auto o = sample_offset(17 * p, 1000 - p, s, g);
                xs.insert(int(o.x * n));
                ys.insert(int(o.y * n));
            }
            EXPECT_EQ(int(xs.size()), n) << n << " samples, pixel " << p;
            EXPECT_EQ(int(ys.size()), n) << n << " samples, pixel " << p;
        }
    }
}

TEST(Sampler, CellsInOrderGiveTheSamplesOneByOne) {
    // The renderer walks a pixel's cells in order and jitters them a packet
    // at a time: the same numbers, to the bit, as any sample asked alone --
    // for square, oblong and prime counts, over each of their rows.
    for (int n : {2, 3, 4, 6, 7, 8, 12, 16, 64, 97, 256}) {
        const StrataGrid g = strata_for(n);
        for (int p = 0; p < 20; ++p) {
            PixelSamples in_order(31 * p, 7 + p, g);
            const PixelSamples any(31 * p, 7 + p, g);
            for (int s = 0; s < n; ++s) {
                const SampleOffset a = jittered(in_order.next_cell(), in_order.unit());
                const SampleOffset b = any[s];
                ASSERT_EQ(a.x, b.x) << n << " samples, sample " << s;
                ASSERT_EQ(a.y, b.y) << n << " samples, sample " << s;
            }
        }
    }
}

TEST(Sampler, CellsAtOnceAreTheCellsInOrder) {
    // The renderer takes a packet's cells at once, each lane any sample of
    // any pixel: the same cells and seeds as next_cell, for any count --
    // powers of two by shifts, others by a multiply and the permutations'
    // walks. Here 8 lanes, each a different pixel's sample, in a shuffled
    // order.
    typedef unsigned Cells __attribute__((vector_size(8 * sizeof(unsigned))));
    typedef std::uint64_t Seeds __attribute__((vector_size(8 * sizeof(std::uint64_t))));
    for (int n : {1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 24, 32, 48, 64, 97, 100, 256, 4093, 4096}) {
        const StrataGrid g = strata_for(n);
        for (int p = 0; p < 20; ++p) {
            Cells px, py;
            std::vector<SampleCell> in_order[8];  // each lane's pixel's cells, in order
            for (int i = 0; i < 8; ++i) {
                px[i] = unsigned(13 * p + 5 * i), py[i] = unsigned(799 - p - i);
                PixelSamples samples(int(px[i]), int(py[i]), g);
                for (int k = 0; k < n; ++k) in_order[i].push_back(samples.next_cell());
            }
            for (int first = 0; first < n; first += 8) {
                Cells s, x, y;
                Seeds seed;
                for (int i = 0; i < 8; ++i) s[i] = unsigned((first + 3 * i) % n);
                cells_at_once(g, PixelKeys<Cells, Seeds>(px, py), s, x, y, seed);
                for (int i = 0; i < 8; ++i) {
                    const SampleCell& c = in_order[i][s[i]];
                    ASSERT_EQ(int(x[i]), c.x) << n << " samples, sample " << s[i];
                    ASSERT_EQ(int(y[i]), c.y) << n << " samples, sample " << s[i];
                    ASSERT_EQ(seed[i], c.seed) << n << " samples, sample " << s[i];
                }
            }
        }
    }
    // One pixel's keys in every lane, worked out once: the same keys.
    for (unsigned p = 0; p < 20; ++p) {
        const PixelKeys<Cells, Seeds> one(7 * p, 3 * p + 1), lanes(Cells{} + 7 * p, Cells{} + (3 * p + 1));
        for (int i = 0; i < 8; ++i) {
            ASSERT_EQ(one.key[i], lanes.key[i]);
            for (int k = 0; k < 4; ++k) {
                ASSERT_EQ(one.column[k][i], lanes.column[k][i]);
                ASSERT_EQ(one.row[k][i], lanes.row[k][i]);
            }
        }
    }
}

TEST(Sampler, PermutationsAreBijectionsForAnyCountAndKey) {
    for (int count = 1; count <= 40; ++count)
        for (std::uint64_t k = 0; k < 200; ++k) {
            const Permutation perm(count, mix64(k));
            std::set<int> seen;
            for (int i = 0; i < count; ++i) {
                const int v = perm(i);
                ASSERT_GE(v, 0);
                ASSERT_LT(v, count);
                seen.insert(v);
            }
            EXPECT_EQ(int(seen.size()), count) << "count " << count << ", key " << k;
        }
    // Keys give other orders: of the 24 orders of 4, the pixels' keys reach many.
    std::set<std::vector<int>> orders;
    for (std::uint64_t k = 0; k < 200; ++k) {
        const Permutation perm(4, mix64(k));
        orders.insert({perm(0), perm(1), perm(2), perm(3)});
    }
    EXPECT_GE(orders.size(), 12u);
}

TEST(Sampler, SamplesDependOnlyOnPixelAndIndex) {
    const StrataGrid g = strata_for(16);
    const auto a = sample_offset(5, 9, 3, g);
    const auto b = sample_offset(5, 9, 3, g);
    const auto c = sample_offset(9, 5, 3, g);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_NE(a.x, c.x);  // another pixel, other jitter
}

TEST(ThreadPool, RunsEveryTaskExactlyOnce) {
    ThreadPool pool(3);
    EXPECT_EQ(pool.size(), 3);
    for (int round = 0; round < 20; ++round) {
        std::vector<std::atomic<int>> seen(1000);
        std::atomic<int> bad_worker{0};
        pool.parallel_for(1000, [&](int task, int worker) {
            seen[size_t(task)]++;
            if (worker < 0 || worker >= 3) bad_worker++;
        });
        for (auto& s : seen) ASSERT_EQ(s.load(), 1);
        EXPECT_EQ(bad_worker.load(), 0);
    }
}

TEST(ThreadPool, RethrowsATasksException) {
    ThreadPool pool(2);
    EXPECT_THROW(pool.parallel_for(100,
                                   [](int task, int) {
                                       if (task == 37) throw std::runtime_error("task 37");
                                   }),
                 std::runtime_error);
    // The pool still works afterwards.
    std::atomic<int> n{0};
    pool.parallel_for(10, [&](int, int) { n++; });
    EXPECT_EQ(n.load(), 10);
}

}  // namespace
}  // namespace fh
