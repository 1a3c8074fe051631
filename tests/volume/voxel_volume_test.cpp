#include "volume/voxel_volume.h"

#include <gtest/gtest.h>

using namespace voxelfair;

TEST(VoxelVolumeBuilder, MergesTouchingVoxelsIntoRuns) {
    VoxelVolumeBuilder b(2, 2, 8);
    ASSERT_TRUE(b.valid());
    EXPECT_TRUE(b.add(0, 0, 1, {1, 0}));
    EXPECT_TRUE(b.add(0, 0, 2, {2, 0}));
    EXPECT_TRUE(b.add(0, 0, 5, {3, 0}));
    EXPECT_TRUE(b.add(1, 1, 7, {4, 0}));
    VoxelVolume v = b.finish();
    ASSERT_EQ(v.columnFirstRun.size(), 5u);
    EXPECT_EQ(v.runs.size(), 3u);
    EXPECT_EQ(v.voxelCount(), 4u);
    EXPECT_EQ(v.columnFirstRun[0], 0u);
    EXPECT_EQ(v.columnFirstRun[1], 2u);  // column (0,0) holds runs [1,3) and [5,6)
    EXPECT_EQ(v.columnFirstRun[3], 2u);  // column (1,1) starts after two empty columns
    EXPECT_EQ(v.columnFirstRun[4], 3u);
    ASSERT_NE(v.find(0, 0, 2), nullptr);
    EXPECT_EQ(v.find(0, 0, 2)->colour, 2);
    EXPECT_EQ(v.find(0, 0, 5)->colour, 3);
    EXPECT_EQ(v.find(1, 1, 7)->colour, 4);
    EXPECT_EQ(v.find(0, 0, 0), nullptr);
    EXPECT_EQ(v.find(0, 0, 3), nullptr);
    EXPECT_EQ(v.find(1, 0, 1), nullptr);
    EXPECT_EQ(v.find(-1, 0, 1), nullptr);
    EXPECT_EQ(v.find(0, 0, 8), nullptr);
}

TEST(VoxelVolumeBuilder, RejectsOutOfOrderAndOutOfRangeVoxels) {
    VoxelVolumeBuilder b(3, 3, 3);
    EXPECT_TRUE(b.add(1, 1, 1, {}));
    EXPECT_FALSE(b.add(1, 1, 1, {}));  // same voxel again
    EXPECT_FALSE(b.add(1, 1, 0, {}));  // lower z in the same column
    EXPECT_FALSE(b.add(0, 1, 2, {}));  // an earlier column
    EXPECT_FALSE(b.add(3, 0, 0, {}));
    EXPECT_FALSE(b.add(0, 0, -1, {}));
    EXPECT_TRUE(b.add(2, 2, 2, {}));
    EXPECT_EQ(b.finish().voxelCount(), 2u);
}

TEST(VoxelVolumeBuilder, RejectsZeroAndHugeSides) {
    EXPECT_FALSE(VoxelVolumeBuilder(0, 1, 1).valid());
    EXPECT_FALSE(VoxelVolumeBuilder(1, kMaxVolumeSide + 1, 1).valid());
    EXPECT_TRUE(VoxelVolumeBuilder(1, 1, kMaxVolumeSide).valid());
}
