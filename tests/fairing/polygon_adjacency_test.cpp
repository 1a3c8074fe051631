#include "fairing/polygon_adjacency.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <vector>

using namespace voxelfair;

namespace {

std::vector<uint32_t> row(const CsrAdjacency &csr, size_t v) { return {csr.begin(v), csr.end(v)}; }

}  // namespace

TEST(FairingVertexNeighbours, QuadMakesEveryOtherVertexANeighbourDiagonalsIncluded) {
    const uint32_t offsets[] = {0, 4};
    const uint32_t quad[] = {0, 1, 2, 3};
    CsrAdjacency n;
    ASSERT_EQ(buildVertexNeighbours(4, offsets, quad, 1, n), PolygonMeshError::None);
    EXPECT_EQ(row(n, 0), (std::vector<uint32_t>{1, 2, 3}));
    EXPECT_EQ(row(n, 2), (std::vector<uint32_t>{0, 1, 3}));
}

TEST(FairingVertexNeighbours, FlatLatticeVertexHasEightNeighbours) {
    // The middle of a 4x4-voxel box face: 4 edge + 4 diagonal neighbours (doc/method.md §3);
    // a box corner has 3 edge + 3 diagonal neighbours.
    const shapes::QuadMesh box = shapes::boxLattice(4, 4, 4);
    CsrAdjacency n;
    ASSERT_EQ(buildVertexNeighbours(box.positions.size(), box.offsets.data(), box.indices.data(), box.quadCount(), n),
              PolygonMeshError::None);
    EXPECT_EQ(n.size(box.find(2, 2, 4)), 8u);
    EXPECT_EQ(n.size(box.find(0, 0, 0)), 6u);
    EXPECT_EQ(n.size(box.find(2, 0, 0)), 8u);  // edge: 4 + 4, shared vertices counted once
}

TEST(FairingVertexNeighbours, MixedPolygonsRepeatedAndIsolatedVertices) {
    // Triangle (0,1,2), quad (1,2,3,4) sharing edge 1-2, a polygon repeating vertex 5, and an
    // isolated vertex 6, a 2-gon and an empty polygon.
    const uint32_t offsets[] = {0, 3, 7, 10, 12, 12};
    const uint32_t indices[] = {0, 1, 2, 1, 2, 3, 4, 5, 0, 5, 3, 4};
    CsrAdjacency n;
    ASSERT_EQ(buildVertexNeighbours(7, offsets, indices, 5, n), PolygonMeshError::None);
    EXPECT_EQ(row(n, 1), (std::vector<uint32_t>{0, 2, 3, 4}));
    EXPECT_EQ(row(n, 5), (std::vector<uint32_t>{0}));  // never its own neighbour
    EXPECT_EQ(row(n, 0), (std::vector<uint32_t>{1, 2, 5}));
    EXPECT_EQ(row(n, 3), (std::vector<uint32_t>{1, 2, 4}));  // the 2-gon adds nothing new
    EXPECT_TRUE(row(n, 6).empty());
}

TEST(FairingVertexNeighbours, ReportsBadInputAndLeavesOutputEmpty) {
    CsrAdjacency n;
    const uint32_t offsets[] = {0, 4};
    const uint32_t outOfRange[] = {0, 1, 2, 9};
    EXPECT_EQ(buildVertexNeighbours(4, offsets, outOfRange, 1, n), PolygonMeshError::IndexOutOfRange);
    EXPECT_EQ(n.rowCount(), 0u);
    const uint32_t decreasing[] = {0, 4, 2};
    const uint32_t quad[] = {0, 1, 2, 3};
    EXPECT_EQ(buildVertexNeighbours(4, decreasing, quad, 2, n), PolygonMeshError::BadOffsets);
    const uint32_t notFromZero[] = {1, 4};
    EXPECT_EQ(buildVertexNeighbours(4, notFromZero, quad, 1, n), PolygonMeshError::BadOffsets);
    EXPECT_EQ(buildVertexNeighbours(4, nullptr, nullptr, 1, n), PolygonMeshError::MissingArray);
    EXPECT_EQ(buildVertexNeighbours(0, nullptr, nullptr, 0, n), PolygonMeshError::None);
    EXPECT_EQ(n.rowCount(), 0u);
}

TEST(FairingVertexPolygons, ListsEachPolygonOnceInOrder) {
    const uint32_t offsets[] = {0, 3, 7, 10};
    const uint32_t indices[] = {0, 1, 2, 1, 2, 3, 4, 5, 0, 5};
    CsrAdjacency p;
    ASSERT_EQ(buildVertexPolygons(7, offsets, indices, 3, p), PolygonMeshError::None);
    EXPECT_EQ(row(p, 1), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(row(p, 5), (std::vector<uint32_t>{2}));
    EXPECT_EQ(row(p, 0), (std::vector<uint32_t>{0, 2}));
    EXPECT_TRUE(row(p, 6).empty());
}
