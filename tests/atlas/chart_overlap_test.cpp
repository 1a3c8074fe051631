// The corner test of the fold checks (chart_overlap.h) on corners numbered by group, as the fold
// checks number a chart's boundary vertices: the same answer as the test by vertex id on random
// sets of fans (closed, pushed past a neighbour's start or past the full turn, with gaps), in
// shuffled order, with groups left without corners.
#include "atlas/chart_overlap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using namespace voxelfair;

TEST(ChartOverlap, CornersByGroupAnswerAsByVertex) {
    const double turn = 6.283185307179586;
    std::mt19937 random(14);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    size_t overlapping = 0, rounds = 0;
    CornerGroups scratch;
    for (int round = 0; round < 400; ++round, ++rounds) {
        const uint32_t groups = 1 + uint32_t(random() % 40);
        std::vector<ChartCorner> corners;
        for (uint32_t g = 0; g < groups; ++g) {
            if (random() % 5 == 0)
                continue;  // a group without corners
            const int fan = 1 + int(random() % 8);
            const double start = unit(random) * turn, share = turn / fan;
            for (int k = 0; k < fan; ++k) {
                if (fan > 2 && random() % 4 == 0)
                    continue;  // a gap in the fan
                double width = share;
                if (random() % 50 == 0)
                    width += 0.01 + unit(random) * share;  // over the next sector's start
                corners.push_back({g, start + k * share, width});
            }
        }
        std::shuffle(corners.begin(), corners.end(), random);
        std::vector<ChartCorner> byVertex = corners;
        const bool expected = cornersOverlap(byVertex);
        EXPECT_EQ(cornersOverlap(corners, groups, scratch), expected) << "round " << round;
        overlapping += expected;
    }
    // Both answers occur.
    EXPECT_GT(overlapping, 0u);
    EXPECT_LT(overlapping, rounds);
}
