#include "attributes/vertex_colours.h"
#include "base/error.h"

#include "attributes/triangulate.h"

#include <gtest/gtest.h>

#include <vector>

using namespace voxelfair;

namespace {

const glm::vec4 kRed(1, 0, 0, 1), kBlue(0, 0, 1, 1);

}  // namespace

// Quads A (red) = (0,1,2,3) and B (blue) = (1,4,5,2) share edge 1-2. Vertex 2 is on A's fixed
// diagonal (a-c = 0-2), so after triangulation it would touch two red triangles and one blue:
// the mean over polygons keeps it an even mix.
TEST(AttributesVertexColours, MeanOverAdjacentPolygonsNotTriangles) {
    const std::vector<uint32_t> offsets = {0, 4, 8};
    const std::vector<uint32_t> quads = {0, 1, 2, 3, 1, 4, 5, 2};
    const glm::vec4 faceColours[] = {kRed, kBlue};
    std::vector<glm::vec4> colours(7);
    ASSERT_NO_THROW(computeVertexColours({nullptr, 7, offsets.data(), quads.data(), 2, faceColours}, colours.data()));
    EXPECT_EQ(colours[0], kRed);
    EXPECT_EQ(colours[3], kRed);
    EXPECT_EQ(colours[4], kBlue);
    EXPECT_EQ(colours[1], (kRed + kBlue) * 0.5f);
    EXPECT_EQ(colours[2], (kRed + kBlue) * 0.5f);
    EXPECT_EQ(colours[6], glm::vec4(0.0f));  // used by no polygon

    // The same on the triangles (colours carried by the triangle -> polygon map) over-weights A.
    std::vector<uint32_t> triangles(12), toPolygon(4), triangleOffsets = {0, 3, 6, 9, 12};
    triangulatePolygons({nullptr, 7, offsets.data(), quads.data(), 2}, triangles.data(), toPolygon.data());
    std::vector<glm::vec4> triangleColours;
    for (uint32_t p : toPolygon)
        triangleColours.push_back(faceColours[p]);
    std::vector<glm::vec4> perTriangle(7);
    computeVertexColours({nullptr, 7, triangleOffsets.data(), triangles.data(), 4, triangleColours.data()},
                         perTriangle.data());
    EXPECT_NEAR(perTriangle[2].x, 2.0f / 3.0f, 1e-6f);
}

TEST(AttributesVertexColours, PolygonRepeatingAVertexCountsOnce) {
    const uint32_t offsets[] = {0, 4, 7};
    const uint32_t indices[] = {0, 1, 0, 2, 0, 3, 4};
    const glm::vec4 faceColours[] = {kRed, kBlue};
    glm::vec4 colours[5];
    ASSERT_NO_THROW(computeVertexColours({nullptr, 5, offsets, indices, 2, faceColours}, colours));
    EXPECT_EQ(colours[0], (kRed + kBlue) * 0.5f);
    const uint32_t bad[] = {0, 1, 0, 2, 0, 3, 5};
    EXPECT_THROW(computeVertexColours({nullptr, 5, offsets, bad, 2, faceColours}, colours), MeshError);
}

// With the vertex polygons built once by the caller (shared with the vertex normals): the same
// colours; polygons built for another mesh are refused before anything is written.
TEST(AttributesVertexColours, PrebuiltVertexPolygonsGiveTheSameColours) {
    const std::vector<uint32_t> offsets = {0, 4, 8};
    const std::vector<uint32_t> quads = {0, 1, 2, 3, 1, 4, 5, 2};
    const glm::vec4 faceColours[] = {kRed, kBlue};
    const PolygonMesh mesh{nullptr, 7, offsets.data(), quads.data(), 2, faceColours};
    std::vector<glm::vec4> plain(7), shared(7);
    computeVertexColours(mesh, plain.data());
    computeVertexColours(mesh, buildVertexPolygons(mesh), shared.data());
    EXPECT_EQ(plain, shared);
    const PolygonMesh fewer{nullptr, 6, offsets.data(), quads.data(), 2, faceColours};
    std::vector<glm::vec4> untouched(7, kRed);
    EXPECT_THROW(computeVertexColours(mesh, buildVertexPolygons(fewer), untouched.data()), MeshError);
    EXPECT_EQ(untouched, std::vector<glm::vec4>(7, kRed));
}
