#include "mesh/polygon_mesh.h"
#include "mesh/triangle_mesh.h"
#include "base/error.h"
#include "mesh/vector_helpers.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

using namespace voxelfair;

namespace {

// The message of the MeshError validate() throws, or "" when it accepts the mesh (a PolygonMesh
// or a TriangleMesh).
template <class Mesh>
std::string rejection(const Mesh &mesh) {
    try {
        validate(mesh);
    } catch (const MeshError &e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(MeshValidation, AcceptsMixedPolygonsAndTheEmptyMesh) {
    const std::vector<glm::vec3> p(5);
    const std::vector<uint32_t> offsets = {0, 3, 7, 7};
    const std::vector<uint32_t> indices = {0, 1, 2, 1, 2, 3, 4};
    EXPECT_EQ(rejection(polygonMesh(p, offsets, indices)), "");
    EXPECT_EQ(rejection(PolygonMesh{}), "");
    const PolygonMesh view = polygonMesh(p, offsets, indices);
    EXPECT_EQ(view.polygonCount, 3u);
    EXPECT_EQ(view.indexCount(), 7u);
    EXPECT_EQ(view.arity(1), 4u);
    EXPECT_EQ(view.polygon(1)[3], 4u);
}

TEST(MeshValidation, NamesThePolygonAndTheProblem) {
    const std::vector<glm::vec3> p(4);
    const std::vector<uint32_t> offsets = {0, 3, 6};
    EXPECT_EQ(rejection(polygonMesh(p, offsets, {0, 1, 2, 2, 3, 9})),
              "polygon 1 uses vertex 9, but there are 4 vertices");
    EXPECT_EQ(rejection(polygonMesh(p, {0, 4, 3}, {0, 1, 2, 3})), "polygon 1: its offsets decrease (4 then 3)");
    EXPECT_EQ(rejection(polygonMesh(p, {1, 4}, {0, 1, 2, 3})), "polygon offsets must start at 0, the first is 1");
    EXPECT_NE(rejection(PolygonMesh{nullptr, 4, offsets.data(), nullptr, 2}).find("no index array"), std::string::npos);
    EXPECT_NE(rejection(PolygonMesh{nullptr, 4, nullptr, nullptr, 2}).find("no polygon offsets"), std::string::npos);
    EXPECT_NE(rejection(PolygonMesh{nullptr, 4, nullptr, nullptr, 0}).find("no positions"), std::string::npos);
    // The polygons alone need no positions.
    EXPECT_NO_THROW(validatePolygons(PolygonMesh{nullptr, 4, nullptr, nullptr, 0}));
}

TEST(MeshValidation, MutableViewWidensToTheReadOnlyOne) {
    std::vector<glm::vec3> p(3, glm::vec3(1.0f));
    const std::vector<uint32_t> offsets = {0, 3}, indices = {0, 1, 2};
    const MutablePolygonMesh m = mutablePolygonMesh(p, offsets, indices);
    const PolygonMesh view = m;
    EXPECT_EQ(view.positions, p.data());
    EXPECT_EQ(view.polygonCount, 1u);
}

TEST(MeshVectorHelpers, NormalizedOrZero) {
    const glm::vec3 n = normalizedOrZero(glm::vec3(3.0f, 0.0f, 4.0f));
    EXPECT_FLOAT_EQ(n.x, 0.6f);
    EXPECT_FLOAT_EQ(n.z, 0.8f);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(normalizedOrZero(glm::vec3(0.0f)), glm::vec3(0.0f));
    EXPECT_EQ(normalizedOrZero(glm::vec3(inf, 0.0f, 0.0f)), glm::vec3(0.0f));
    EXPECT_EQ(normalizedOrZero(glm::vec3(nan, 1.0f, 0.0f)), glm::vec3(0.0f));
    EXPECT_EQ(normalizedOrZero(glm::vec3(3e38f, 3e38f, 0.0f)), glm::vec3(0.0f));  // squared length overflows
    EXPECT_TRUE(isFinite(glm::vec3(1.0f)));
    EXPECT_FALSE(isFinite(glm::vec3(1.0f, nan, 0.0f)));
}

TEST(TriangleMeshValidation, AcceptsTrianglesAndTheEmptyMesh) {
    const std::vector<glm::vec3> p(4);
    const std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
    const TriangleMesh view = triangleMesh(p, triangles);
    EXPECT_EQ(view.faceCount, 2u);
    EXPECT_EQ(view.vertexCount, 4u);
    EXPECT_EQ(rejection(view), "");
    EXPECT_EQ(rejection(TriangleMesh{}), "");
    // Vertices without faces are no error either (nothing reads them).
    EXPECT_EQ(rejection(TriangleMesh{nullptr, 3, nullptr, 0}), "");
}

TEST(TriangleMeshValidation, NamesTheFaceAndTheProblem) {
    const std::vector<glm::vec3> p(4);
    std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
    triangles[4] = 7;
    const std::string outOfRange = rejection(triangleMesh(p, triangles));
    EXPECT_NE(outOfRange.find("face 1"), std::string::npos) << outOfRange;
    EXPECT_NE(outOfRange.find("vertex 7"), std::string::npos) << outOfRange;

    EXPECT_NE(rejection(TriangleMesh{p.data(), p.size(), nullptr, 2}).find("no triangle indices"), std::string::npos);
    EXPECT_NE(rejection(TriangleMesh{nullptr, p.size(), triangles.data(), 2}).find("no vertex positions"),
              std::string::npos);
    EXPECT_NE(rejection(TriangleMesh{p.data(), 0, triangles.data(), 2}).find("no vertex positions"), std::string::npos);
}
