#include "attributes/face_normals.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

using namespace voxelfair;

TEST(AttributesFaceNormals, BoxQuadsPointOutOfTheSolid) {
    const shapes::QuadMesh box = shapes::boxLattice(3, 2, 4);
    std::vector<glm::vec3> normals(box.quadCount());
    ASSERT_NO_THROW(computePolygonNormals(
        {box.positions.data(), box.positions.size(), box.offsets.data(), box.indices.data(), box.quadCount()},
        normals.data()));
    const glm::vec3 centre(1.5f, 1.0f, 2.0f);
    for (size_t q = 0; q < box.quadCount(); ++q) {
        glm::vec3 mid(0.0f);
        for (int k = 0; k < 4; ++k)
            mid += box.positions[box.indices[4 * q + k]] * 0.25f;
        const glm::vec3 out = mid - centre;
        // Unit, axis-aligned, and on the outer side.
        EXPECT_FLOAT_EQ(glm::length(normals[q]), 1.0f);
        EXPECT_FLOAT_EQ(std::fabs(normals[q].x) + std::fabs(normals[q].y) + std::fabs(normals[q].z), 1.0f);
        EXPECT_GT(glm::dot(normals[q], out), 0.0f) << q;
    }
}

TEST(AttributesFaceNormals, NonPlanarQuadIsTheMeanOfItsUnitTriangleNormals) {
    // Triangle (a,b,c) lies in z = 0; (a,c,d) is tilted and twice as large: with unit triangle
    // normals both count the same, whatever their areas.
    const glm::vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 3, 2}};
    const uint32_t offsets[] = {0, 4};
    const uint32_t quad[] = {0, 1, 2, 3};
    glm::vec3 n;
    ASSERT_NO_THROW(computePolygonNormals({p, 4, offsets, quad, 1}, &n));
    const glm::vec3 expected = glm::normalize(triangleNormal(p[0], p[1], p[2]) + triangleNormal(p[0], p[2], p[3]));
    EXPECT_NEAR(glm::distance(n, expected), 0.0f, 1e-6f);
}

TEST(AttributesFaceNormals, DegeneratePolygonsGetZero) {
    const glm::vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}};
    const uint32_t offsets[] = {0, 3, 5};
    const uint32_t indices[] = {0, 1, 2, 0, 3};
    glm::vec3 n[2];
    ASSERT_NO_THROW(computePolygonNormals({p, 4, offsets, indices, 2}, n));
    EXPECT_EQ(n[0], glm::vec3(0.0f));
    EXPECT_EQ(n[1], glm::vec3(0.0f));
}
