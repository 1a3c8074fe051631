#include "fairing/voxel_size.h"

#include "fairing/lanczos_fairing.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

using namespace voxelfair;

namespace {

float detect(const shapes::QuadMesh &m, float expected = 0.0f, int threads = 1) {
    return detectVoxelSize({m.positions.data(), m.positions.size(), m.offsets.data(), m.indices.data(), m.quadCount()},
                           expected, threads);
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

// A size known from the importer is kept while the mesh still has edges of that length: on thin
// bars (1 x 1 and 2 x 1 voxels, 10 to 60 long, any scale and offset) faired by the paper's pass,
// whose cross-sections shrink into a mode of their own, it is the bar's voxel; on the raw bar too;
// on the faired bar rescaled since, it is not kept, and the size is what detection finds there.
TEST(FairingVoxelSize, AnImportedSizeHoldsWhileTheMeshKeepsItsEdges) {
    std::mt19937_64 random(20261126);
    std::uniform_int_distribution<int> length(10, 60), width(1, 2);
    std::uniform_real_distribution<float> scale(0.05f, 3.0f), offset(-50.0f, 50.0f);
    for (int i = 0; i < 12; ++i) {
        const int n = length(random), w = width(random);
        const float s = scale(random);
        const glm::vec3 o(offset(random), offset(random), offset(random));
        shapes::QuadMesh bar = shapes::boxLattice(w, 1, n);
        for (glm::vec3 &p : bar.positions)
            p = p * s + o;
        SCOPED_TRACE("bar " + std::to_string(w) + " x 1 x " + std::to_string(n) + " at scale " + std::to_string(s));
        EXPECT_NEAR(detect(bar, s), s, 1e-6f * s);
        fairModifiedLanczos(
            {bar.positions.data(), bar.positions.size(), bar.offsets.data(), bar.indices.data(), bar.quadCount()},
            nullptr);
        EXPECT_EQ(detect(bar, s), s);
        const float alone = detect(bar);
        if (w == 1) {  // the shrunk cross-sections (0.46 voxels) are as many as the voxel's edges
            EXPECT_LT(alone, 0.9f * s);
        }
        for (glm::vec3 &p : bar.positions)
            p *= 1.5f;
        EXPECT_NEAR(detect(bar, s), 1.5f * alone, 1e-3f * s) << "a rescaled mesh keeps no edge of the imported length";
    }
}

// The edges are measured in bands on threads and joined in order: any thread count gives the same
// size, to the bit, on a large box (28000 quads, enough for three bands) whose vertices were
// jittered so that its lengths spread over many bins, and with an imported size.
TEST(FairingVoxelSize, AnyThreadCountGivesTheSameSize) {
    shapes::QuadMesh box = shapes::boxLattice(100, 100, 20);
    std::mt19937 random(14);
    std::uniform_real_distribution<float> jitter(-0.04f, 0.04f);
    for (glm::vec3 &p : box.positions)
        p = 0.37f * (p + glm::vec3(jitter(random), jitter(random), jitter(random)));
    const float one = detect(box);
    EXPECT_NEAR(one, 0.37f, 0.05f);
    EXPECT_NE(one, 0.37f);  // a bin's mean, not the lattice edge
    for (const int threads : {2, 3, 4}) {
        EXPECT_EQ(detect(box, 0.0f, threads), one) << threads;
        EXPECT_EQ(detect(box, 0.37f, threads), detect(box, 0.37f)) << threads;
    }
}
