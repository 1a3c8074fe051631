#include "attributes/triangulate.h"
#include "base/error.h"

#include <gtest/gtest.h>

#include <vector>

using namespace voxelfair;

TEST(AttributesTriangulate, QuadsSplitAlongTheFixedDiagonalAC) {
    // A quad, a pentagon, a 2-gon (no triangle) and a triangle.
    const std::vector<uint32_t> offsets = {0, 4, 9, 11, 14};
    const std::vector<uint32_t> indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4};
    ASSERT_EQ(countFanTriangles({nullptr, 0, offsets.data(), nullptr, 4}), 2u + 3u + 0u + 1u);
    std::vector<uint32_t> triangles(3 * 6), toPolygon(6);
    ASSERT_NO_THROW(
        triangulatePolygons({nullptr, 9, offsets.data(), indices.data(), 4}, triangles.data(), toPolygon.data()));
    EXPECT_EQ(triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 4, 7, 8, 2, 3, 4}));
    EXPECT_EQ(toPolygon, (std::vector<uint32_t>{0, 0, 1, 1, 1, 3}));
}

TEST(AttributesTriangulate, RejectsBadIndicesWithoutWriting) {
    const uint32_t offsets[] = {0, 4};
    const uint32_t quad[] = {0, 1, 2, 4};
    std::vector<uint32_t> triangles(6, 77);
    EXPECT_THROW(triangulatePolygons({nullptr, 4, offsets, quad, 1}, triangles.data(), nullptr), MeshError);
    EXPECT_EQ(triangles, std::vector<uint32_t>(6, 77));
}
