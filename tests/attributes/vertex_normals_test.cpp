#include "attributes/vertex_normals.h"

#include "attributes/face_normals.h"
#include "base/error.h"
#include "attributes/triangulate.h"
#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

using namespace voxelfair;

namespace {

constexpr VertexNormalOptions kPlainMean{2.0f};  // nothing counts as repeated

float angleDegrees(const glm::vec3 &a, const glm::vec3 &b) {
    return std::acos(std::min(1.0f, glm::dot(a, b))) * 180.0f / 3.14159265f;
}

// Vertex 0 shared by one polygon per given normal (polygon k = {0, k + 1}).
std::vector<glm::vec3> fanNormal(const std::vector<glm::vec3> &faceNormals, const VertexNormalOptions &o = {}) {
    std::vector<uint32_t> offsets = {0}, indices;
    for (uint32_t k = 0; k < faceNormals.size(); ++k) {
        indices.insert(indices.end(), {0, k + 1});
        offsets.push_back(uint32_t(indices.size()));
    }
    std::vector<glm::vec3> normals(faceNormals.size() + 2);  // + one isolated vertex
    EXPECT_NO_THROW(computeVertexNormals({nullptr, normals.size(), offsets.data(), indices.data(), faceNormals.size()},
                                         faceNormals.data(), normals.data(), o));
    return normals;
}

}  // namespace

// The inner corner of an L-shaped ledge on a voxel surface: three top quads (+z) and the two
// walls of the notch (+x, +y) meet there. Repeated directions count once: (1,1,1)/sqrt3, where
// a plain mean leans 25 degrees towards +z.
TEST(AttributesVertexNormals, RepeatedDirectionsCountOnce) {
    const glm::vec3 z(0, 0, 1), x(1, 0, 0), y(0, 1, 0);
    const std::vector<glm::vec3> faces = {z, z, x, z, y};
    const glm::vec3 distinct = fanNormal(faces)[0];
    const glm::vec3 plain = fanNormal(faces, kPlainMean)[0];
    EXPECT_NEAR(glm::distance(distinct, glm::normalize(glm::vec3(1, 1, 1))), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(plain, glm::normalize(glm::vec3(1, 1, 3))), 0.0f, 1e-6f);
    EXPECT_GT(angleDegrees(distinct, plain), 20.0f);
}

TEST(AttributesVertexNormals, ToleranceMergesOnlyNearlyIdenticalDirections) {
    const glm::vec3 z(0, 0, 1), x(1, 0, 0);
    const glm::vec3 zRounded = glm::normalize(glm::vec3(1e-4f, 0, 1));  // dot = 1 - 5e-9: same direction
    const glm::vec3 zTilted = glm::normalize(glm::vec3(0.05f, 0, 1));   // dot = 1 - 1.2e-3: distinct
    EXPECT_NEAR(glm::distance(fanNormal({z, zRounded, x})[0], glm::normalize(z + x)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(fanNormal({z, zTilted, x})[0], glm::normalize(z + zTilted + x)), 0.0f, 1e-6f);
}

TEST(AttributesVertexNormals, ZeroFacesIgnoredCancellingAndIsolatedGiveZero) {
    const std::vector<glm::vec3> n = fanNormal({glm::vec3(0, 0, 1), glm::vec3(0.0f), glm::vec3(0, 0, -1)});
    EXPECT_EQ(n[0], glm::vec3(0.0f));  // +z and -z cancel
    EXPECT_EQ(n[1], glm::vec3(0, 0, 1));
    EXPECT_EQ(n[2], glm::vec3(0.0f));  // its only face is degenerate
    EXPECT_EQ(n[4], glm::vec3(0.0f));  // isolated
}

// A 1 x 2 x 3 box made of six single quads, split into triangles along a-c: at a corner the
// three sides contribute one or two triangles each, of different sizes. Counting directions,
// every corner gets exactly (+-1,+-1,+-1)/sqrt3; a plain mean of the triangles does not.
TEST(AttributesVertexNormals, TriangulatedBoxCornersAreExactDiagonals) {
    shapes::QuadMesh box = shapes::boxLattice(1, 1, 1);
    for (glm::vec3 &p : box.positions)
        p *= glm::vec3(1.0f, 2.0f, 3.0f);
    const size_t triangleCount = countFanTriangles({nullptr, 0, box.offsets.data(), nullptr, box.quadCount()});
    std::vector<uint32_t> triangles(3 * triangleCount), offsets(triangleCount + 1);
    ASSERT_NO_THROW(
        triangulatePolygons({nullptr, box.positions.size(), box.offsets.data(), box.indices.data(), box.quadCount()},
                            triangles.data(), nullptr));
    for (size_t t = 0; t <= triangleCount; ++t)
        offsets[t] = uint32_t(3 * t);
    std::vector<glm::vec3> faceNormals(triangleCount), distinct(8), plain(8);
    ASSERT_NO_THROW(computePolygonNormals({box.positions.data(), 8, offsets.data(), triangles.data(), triangleCount},
                                          faceNormals.data()));
    ASSERT_NO_THROW(computeVertexNormals({nullptr, 8, offsets.data(), triangles.data(), triangleCount},
                                         faceNormals.data(), distinct.data()));
    computeVertexNormals({nullptr, 8, offsets.data(), triangles.data(), triangleCount}, faceNormals.data(),
                         plain.data(), kPlainMean);
    const glm::vec3 centre(0.5f, 1.0f, 1.5f);
    float worstPlain = 0.0f;
    for (int v = 0; v < 8; ++v) {
        const glm::vec3 diagonal = glm::normalize(glm::sign(box.positions[v] - centre));
        EXPECT_NEAR(glm::distance(distinct[v], diagonal), 0.0f, 1e-6f) << v;
        worstPlain = std::max(worstPlain, angleDegrees(plain[v], diagonal));
    }
    EXPECT_GT(worstPlain, 10.0f);  // unequal triangle counts (2:1:1) tilt it by up to 19.5 degrees
}

// With the vertex polygons built once by the caller (shared with the vertex colours): the same
// normals; polygons built for another mesh are refused before anything is written.
TEST(AttributesVertexNormals, PrebuiltVertexPolygonsGiveTheSameNormals) {
    const glm::vec3 z(0, 0, 1), x(1, 0, 0), y(0, 1, 0);
    const std::vector<glm::vec3> faceNormals = {z, z, x, z, y};
    std::vector<uint32_t> offsets = {0}, indices;
    for (uint32_t k = 0; k < faceNormals.size(); ++k) {
        indices.insert(indices.end(), {0, k + 1});
        offsets.push_back(uint32_t(indices.size()));
    }
    const PolygonMesh mesh{nullptr, faceNormals.size() + 2, offsets.data(), indices.data(), faceNormals.size()};
    std::vector<glm::vec3> plain(mesh.vertexCount), shared(mesh.vertexCount);
    computeVertexNormals(mesh, faceNormals.data(), plain.data());
    computeVertexNormals(mesh, buildVertexPolygons(mesh), faceNormals.data(), shared.data());
    EXPECT_EQ(plain, shared);
    EXPECT_GT(glm::length(shared[0]), 0.99f);  // the fan's vertex has a normal
    PolygonMesh fewer = mesh;
    fewer.vertexCount -= 1;
    std::vector<glm::vec3> untouched(mesh.vertexCount, x);
    EXPECT_THROW(computeVertexNormals(mesh, buildVertexPolygons(fewer), faceNormals.data(), untouched.data()),
                 MeshError);
    EXPECT_EQ(untouched, std::vector<glm::vec3>(mesh.vertexCount, x));
}
