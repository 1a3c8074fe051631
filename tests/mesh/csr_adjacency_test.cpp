#include "mesh/csr_adjacency.h"
#include "base/error.h"

#include "shapes/box_lattice.h"

#include <gtest/gtest.h>

#include <vector>

using namespace voxelfair;

namespace {

std::vector<uint32_t> row(const CsrAdjacency &csr, size_t v) { return {csr.begin(v), csr.end(v)}; }

}  // namespace

TEST(MeshVertexNeighbours, QuadMakesEveryOtherVertexANeighbourDiagonalsIncluded) {
    const uint32_t offsets[] = {0, 4};
    const uint32_t quad[] = {0, 1, 2, 3};
    CsrAdjacency n;
    ASSERT_NO_THROW(buildVertexNeighbours({nullptr, 4, offsets, quad, 1}, n));
    EXPECT_EQ(row(n, 0), (std::vector<uint32_t>{1, 2, 3}));
    EXPECT_EQ(row(n, 2), (std::vector<uint32_t>{0, 1, 3}));
}

TEST(MeshVertexNeighbours, FlatLatticeVertexHasEightNeighbours) {
    // The middle of a 4x4-voxel box face: 4 edge + 4 diagonal neighbours (doc/method.md §3);
    // a box corner has 3 edge + 3 diagonal neighbours.
    const shapes::QuadMesh box = shapes::boxLattice(4, 4, 4);
    CsrAdjacency n;
    ASSERT_NO_THROW(buildVertexNeighbours(
        {nullptr, box.positions.size(), box.offsets.data(), box.indices.data(), box.quadCount()}, n));
    EXPECT_EQ(n.size(box.find(2, 2, 4)), 8u);
    EXPECT_EQ(n.size(box.find(0, 0, 0)), 6u);
    EXPECT_EQ(n.size(box.find(2, 0, 0)), 8u);  // edge: 4 + 4, shared vertices counted once
}

TEST(MeshVertexNeighbours, MixedPolygonsRepeatedAndIsolatedVertices) {
    // Triangle (0,1,2), quad (1,2,3,4) sharing edge 1-2, a polygon repeating vertex 5, and an
    // isolated vertex 6, a 2-gon and an empty polygon.
    const uint32_t offsets[] = {0, 3, 7, 10, 12, 12};
    const uint32_t indices[] = {0, 1, 2, 1, 2, 3, 4, 5, 0, 5, 3, 4};
    CsrAdjacency n;
    ASSERT_NO_THROW(buildVertexNeighbours({nullptr, 7, offsets, indices, 5}, n));
    EXPECT_EQ(row(n, 1), (std::vector<uint32_t>{0, 2, 3, 4}));
    EXPECT_EQ(row(n, 5), (std::vector<uint32_t>{0}));  // never its own neighbour
    EXPECT_EQ(row(n, 0), (std::vector<uint32_t>{1, 2, 5}));
    EXPECT_EQ(row(n, 3), (std::vector<uint32_t>{1, 2, 4}));  // the 2-gon adds nothing new
    EXPECT_TRUE(row(n, 6).empty());
}

TEST(MeshVertexNeighbours, ReportsBadInputAndLeavesOutputEmpty) {
    CsrAdjacency n;
    const uint32_t offsets[] = {0, 4};
    const uint32_t outOfRange[] = {0, 1, 2, 9};
    EXPECT_THROW(buildVertexNeighbours({nullptr, 4, offsets, outOfRange, 1}, n), MeshError);
    EXPECT_EQ(n.rowCount(), 0u);
    const uint32_t decreasing[] = {0, 4, 2};
    const uint32_t quad[] = {0, 1, 2, 3};
    EXPECT_THROW(buildVertexNeighbours({nullptr, 4, decreasing, quad, 2}, n), MeshError);
    const uint32_t notFromZero[] = {1, 4};
    EXPECT_THROW(buildVertexNeighbours({nullptr, 4, notFromZero, quad, 1}, n), MeshError);
    EXPECT_THROW(buildVertexNeighbours({nullptr, 4, nullptr, nullptr, 1}, n), MeshError);
    EXPECT_NO_THROW(buildVertexNeighbours({nullptr, 0, nullptr, nullptr, 0}, n));
    EXPECT_EQ(n.rowCount(), 0u);
}

TEST(MeshVertexPolygons, ListsEachPolygonOnceInOrder) {
    const uint32_t offsets[] = {0, 3, 7, 10};
    const uint32_t indices[] = {0, 1, 2, 1, 2, 3, 4, 5, 0, 5};
    const CsrAdjacency p = buildVertexPolygons({nullptr, 7, offsets, indices, 3});
    EXPECT_EQ(row(p, 1), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(row(p, 5), (std::vector<uint32_t>{2}));
    EXPECT_EQ(row(p, 0), (std::vector<uint32_t>{0, 2}));
    EXPECT_TRUE(row(p, 6).empty());
}
