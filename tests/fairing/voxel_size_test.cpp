#include "fairing/voxel_size.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <limits>

using namespace voxelfair;

namespace {

float detect(const shapes::QuadMesh &m) {
    return detectVoxelSize({m.positions.data(), m.positions.size(), m.offsets.data(), m.indices.data(), m.quadCount()});
}

}  // namespace

TEST(FairingVoxelSize, IsTheLatticeEdgeOfAScaledVoxelMesh) {
    shapes::QuadMesh box = shapes::boxLattice(5, 3, 2);
    EXPECT_EQ(detect(box), 1.0f);
    for (glm::vec3 &p : box.positions)
        p = p * 0.0625f + glm::vec3(-7.0f, 3.0f, 100.0f);
    EXPECT_NEAR(detect(box), 0.0625f, 1e-6f);
}

TEST(FairingVoxelSize, IgnoresMinorityLengthsDegenerateEdgesAndBadValues) {
    shapes::QuadMesh box = shapes::boxLattice(6, 6, 6);
    box.positions[box.find(0, 0, 0)] = glm::vec3(0.3f, 0.2f, 0.1f);  // a few odd edges
    box.positions[box.find(3, 3, 6)] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    box.positions[box.find(3, 0, 0)] = box.positions[box.find(2, 0, 0)];  // zero-length edges
    EXPECT_EQ(detect(box), 1.0f);
}

TEST(FairingVoxelSize, ZeroWhenNothingToMeasure) {
    EXPECT_EQ(detectVoxelSize({nullptr, 0, nullptr, nullptr, 0}), 0.0f);
    const glm::vec3 same[] = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
    const uint32_t offsets[] = {0, 3};
    const uint32_t tri[] = {0, 1, 2};
    EXPECT_EQ(detectVoxelSize({same, 3, offsets, tri, 1}), 0.0f);
    const uint32_t outOfRange[] = {0, 1, 7};
    const glm::vec3 p[] = {glm::vec3(0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f)};
    EXPECT_EQ(detectVoxelSize({p, 3, offsets, outOfRange, 1}), 2.0f);  // the one valid edge
}
