#include "extraction/cavity_fill.h"

#include "shapes/dense_grid.h"
#include "reference_surface.h"

#include <gtest/gtest.h>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

constexpr Voxel kFill{200, 7};

// The run layout the builder guarantees: sorted, disjoint, non-touching runs; contiguous voxels.
void expectWellFormed(const VoxelVolume &v) {
    ASSERT_EQ(v.columnFirstRun.size(), size_t(v.sizeX) * v.sizeY + 1);
    EXPECT_EQ(v.columnFirstRun.front(), 0u);
    EXPECT_EQ(v.columnFirstRun.back(), v.runs.size());
    uint32_t nextVoxel = 0;
    for (size_t c = 0; c + 1 < v.columnFirstRun.size(); ++c) {
        ASSERT_LE(v.columnFirstRun[c], v.columnFirstRun[c + 1]);
        for (uint32_t r = v.columnFirstRun[c]; r < v.columnFirstRun[c + 1]; ++r) {
            const VoxelRun &run = v.runs[r];
            EXPECT_LT(run.zBegin, run.zEnd);
            EXPECT_LE(run.zEnd, v.sizeZ);
            if (r > v.columnFirstRun[c]) {
                EXPECT_GT(run.zBegin, v.runs[r - 1].zEnd);
            }
            EXPECT_EQ(run.firstVoxel, nextVoxel);
            nextVoxel += run.zEnd - run.zBegin;
        }
    }
    EXPECT_EQ(nextVoxel, v.voxels.size());
}

// fillEnclosedCavities against the dense flood fill: same solid set, original payloads kept,
// filled voxels carry the fill payload.
void expectMatchesReference(const DenseGrid &grid) {
    const ReferenceSolid ref = referenceSolid(grid);
    size_t filled = 12345;
    const VoxelVolume out = fillEnclosedCavities(grid.toVolume(), &filled, kFill);
    EXPECT_EQ(filled, ref.cavityVoxels);
    expectWellFormed(out);
    EXPECT_EQ(out.voxelCount(), ref.count());
    for (int z = 0; z < grid.sizeZ; ++z)
        for (int y = 0; y < grid.sizeY; ++y)
            for (int x = 0; x < grid.sizeX; ++x) {
                const Voxel *v = out.find(x, y, z);
                ASSERT_EQ(v != nullptr, ref.at(x, y, z)) << x << "," << y << "," << z;
                if (!v)
                    continue;
                const Voxel expected = grid.at(x, y, z) ? grid.payload[grid.index(x, y, z)] : kFill;
                EXPECT_EQ(v->colour, expected.colour);
                EXPECT_EQ(v->normal, expected.normal);
            }
}

}  // namespace

TEST(FillEnclosedCavities, FillsTheInsideOfAHollowBox) {
    const DenseGrid g = hollowBox(5);
    size_t filled = 0;
    const VoxelVolume out = fillEnclosedCavities(g.toVolume(), &filled, kFill);
    EXPECT_EQ(filled, 27u);
    EXPECT_EQ(out.voxelCount(), 125u);
    EXPECT_EQ(out.runs.size(), 25u);  // each column became one run
    ASSERT_NE(out.find(2, 2, 2), nullptr);
    EXPECT_EQ(out.find(2, 2, 2)->colour, kFill.colour);
    expectMatchesReference(g);
    expectMatchesReference(hollowBox(9, 3));
}

TEST(FillEnclosedCavities, LeavesACavityOpenThroughOneHole) {
    for (int face = 0; face < 6; ++face) {
        DenseGrid g = hollowBox(5);
        const int hole[6][3] = {{0, 2, 2}, {4, 2, 2}, {2, 0, 2}, {2, 4, 2}, {2, 2, 0}, {2, 2, 4}};
        g.set(hole[face][0], hole[face][1], hole[face][2], false);
        size_t filled = 99;
        const VoxelVolume out = fillEnclosedCavities(g.toVolume(), &filled);
        EXPECT_EQ(filled, 0u) << "hole in face " << face;
        EXPECT_EQ(out.voxelCount(), g.count());
    }
}

TEST(FillEnclosedCavities, FillsNestedCavitiesAroundAnIsland) {
    DenseGrid g = hollowBox(9);
    for (int z = 3; z < 6; ++z)
        for (int y = 3; y < 6; ++y)
            for (int x = 3; x < 6; ++x)
                g.set(x, y, z);  // a solid core floating inside
    g.set(4, 4, 4, false);       // with a cavity of its own
    size_t filled = 0;
    fillEnclosedCavities(g.toVolume(), &filled);
    EXPECT_EQ(filled, 7u * 7 * 7 - 26);
    expectMatchesReference(g);
}

TEST(FillEnclosedCavities, CavityReachingTheOutsideThroughAWindingTunnelStaysOpen) {
    // A tunnel that turns in every axis: the interior is reachable only through other columns.
    DenseGrid g = hollowBox(7);
    for (int z = 1; z < 6; ++z)
        for (int y = 1; y < 6; ++y)
            for (int x = 1; x < 6; ++x)
                g.set(x, y, z);  // solid, then carve:
    const int path[][3] = {{3, 3, 3}, {3, 3, 2}, {3, 2, 2}, {2, 2, 2}, {2, 2, 1}, {2, 1, 1}, {1, 1, 1}, {0, 1, 1}};
    for (const auto &p : path)
        g.set(p[0], p[1], p[2], false);
    size_t filled = 99;
    fillEnclosedCavities(g.toVolume(), &filled);
    EXPECT_EQ(filled, 0u);
    g.set(0, 1, 1);  // close the mouth: the whole tunnel becomes a cavity
    fillEnclosedCavities(g.toVolume(), &filled);
    EXPECT_EQ(filled, 7u);
}

TEST(FillEnclosedCavities, GapsBelowAndAboveTheRunsAndInBorderColumnsAreExterior) {
    DenseGrid cup = hollowBox(5);
    for (int y = 1; y < 4; ++y)
        for (int x = 1; x < 4; ++x)
            cup.set(x, y, 4, false);  // open at the top
    size_t filled = 99;
    fillEnclosedCavities(cup.toVolume(), &filled);
    EXPECT_EQ(filled, 0u);

    // A one-voxel notch in a border column, walled in on every side but the padding.
    DenseGrid notch = box(3, 3, 3);
    notch.set(0, 1, 1, false);
    fillEnclosedCavities(notch.toVolume(), &filled);
    EXPECT_EQ(filled, 0u);
}

TEST(FillEnclosedCavities, MatchesADenseFloodFillOnRandomGrids) {
    uint32_t seed = 1;
    for (const double density : {0.5, 0.65, 0.8})
        for (const auto &size :
             {std::array<int, 3>{6, 6, 6}, std::array<int, 3>{9, 5, 12}, std::array<int, 3>{16, 16, 3}})
            for (int i = 0; i < 6; ++i, ++seed) {
                SCOPED_TRACE(testing::Message() << "seed " << seed << " density " << density);
                expectMatchesReference(randomGrid(size[0], size[1], size[2], density, seed));
            }
}

TEST(FillEnclosedCavities, EmptyVolumesStayEmpty) {
    size_t filled = 99;
    EXPECT_TRUE(fillEnclosedCavities(VoxelVolume{}, &filled).empty());
    EXPECT_EQ(filled, 0u);
    const VoxelVolume out = fillEnclosedCavities(VoxelVolumeBuilder(4, 3, 2).finish(), &filled);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(out.columnFirstRun.size(), 13u);
    EXPECT_EQ(filled, 0u);
}

TEST(FillEnclosedCavities, WorksInTheLargestVolumeWithoutTouchingItsBoundingBox) {
    // kMaxVolumeSide^3 cells would be 8 GiB as a dense grid; the runs hold a 5^3 shell.
    VoxelVolumeBuilder b(kMaxVolumeSide, kMaxVolumeSide, kMaxVolumeSide);
    const int o = 1000;
    for (int y = o; y < o + 5; ++y)
        for (int x = o; x < o + 5; ++x)
            for (int z = o; z < o + 5; ++z) {
                const bool wall = x == o || y == o || z == o || x == o + 4 || y == o + 4 || z == o + 4;
                if (wall) {
                    ASSERT_TRUE(b.add(x, y, z, {}));
                }
            }
    size_t filled = 0;
    const VoxelVolume out = fillEnclosedCavities(b.finish(), &filled);
    EXPECT_EQ(filled, 27u);
    EXPECT_EQ(out.voxelCount(), 125u);
}
