#include "mesh/triangle_mesh.h"
#include "base/error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace voxelfair;

namespace {

// The message of the MeshError validate() throws, or "" when it accepts the mesh.
std::string rejection(const TriangleMesh &mesh) {
    try {
        validate(mesh);
    } catch (const MeshError &e) {
        return e.what();
    }
    return "";
}

}  // namespace

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
