#include "fixtures/vxl_fixtures.h"
#include "formats/vxl_placement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace voxelfair;

namespace {

// A section of the given size whose bounds give voxel scale (0.5, 2, 0.7).
VxlSection scaledSection() {
    VxlSection s = fixtures::makeSection("s", fixtures::volumeFromVoxels(4, 3, 10, {}));
    s.minBounds = {-1.0f, -3.0f, 0.5f};
    s.maxBounds = {1.0f, 3.0f, 7.5f};
    s.scale = 0.25f;
    return s;
}

glm::vec3 apply(const glm::mat4 &m, glm::vec3 v) { return glm::vec3(m * glm::vec4(v, 1.0f)); }

void expectNear(glm::vec3 a, glm::vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

}  // namespace

TEST(VxlPlacement, VoxelScaleIsBoundsOverSize) {
    const glm::vec3 sf = scaledSection().voxelScale();
    EXPECT_FLOAT_EQ(sf.x, 0.5f);
    EXPECT_FLOAT_EQ(sf.y, 2.0f);
    EXPECT_FLOAT_EQ(sf.z, 0.7f);
}

TEST(VxlPlacement, DegenerateVoxelScaleIsOne) {
    VxlSection s = scaledSection();
    s.maxBounds.x = s.minBounds.x;                           // zero extent
    s.maxBounds.y = s.minBounds.y - 1.0f;                    // negative extent
    s.maxBounds.z = std::numeric_limits<float>::infinity();  // non-finite
    EXPECT_EQ(s.voxelScale(), glm::vec3(1.0f));
    VxlSection unsized;  // size 0
    unsized.maxBounds = glm::vec3(5.0f);
    EXPECT_EQ(unsized.voxelScale(), glm::vec3(1.0f));
}

TEST(VxlPlacement, HvaMatrixTranslationIsScaledBySectionScale) {
    const VxlSection s = scaledSection();
    // R: a quarter turn about z (x -> y, y -> -x); t = (8, -4, 12).
    const Matrix3x4 hva = {0, -1, 0, 8, 1, 0, 0, -4, 0, 0, 1, 12};
    const glm::mat4 m = sectionToModel(s, &hva);
    for (glm::vec3 v : {glm::vec3(0), glm::vec3(1, 2, 3), glm::vec3(4, 3, 10)}) {
        const glm::vec3 local = s.minBounds + v * glm::vec3(0.5f, 2.0f, 0.7f);
        const glm::vec3 rotated(-local.y, local.x, local.z);
        expectNear(apply(m, v), rotated + glm::vec3(8, -4, 12) * 0.25f);
    }
}

TEST(VxlPlacement, WithoutHvaTheTailerMatrixIsUsedAsStored) {
    VxlSection s = scaledSection();
    s.transform = {1, 0, 0, 3, 0, 0, -1, 5, 0, 1, 0, -2};  // y -> z, z -> -y
    const glm::mat4 m = sectionToModel(s, nullptr);
    const glm::vec3 v(2, 1, 4);
    const glm::vec3 local = s.minBounds + v * glm::vec3(0.5f, 2.0f, 0.7f);
    expectNear(apply(m, v), glm::vec3(local.x, -local.z, local.y) + glm::vec3(3, 5, -2));
}

TEST(VxlPlacement, EditorDefaultsPlaceVoxelsAtTheirBounds) {
    // Identity matrices and sf = 1: voxel (x, y, z) lands at minBounds + (x, y, z).
    const VxlSection s = fixtures::makeSection("s", fixtures::volumeFromVoxels(6, 4, 3, {}));
    expectNear(apply(sectionToModel(s, &kIdentity3x4), glm::vec3(6, 4, 3)), s.maxBounds);
    expectNear(apply(sectionToModel(s, nullptr), glm::vec3(0)), s.minBounds);
}
