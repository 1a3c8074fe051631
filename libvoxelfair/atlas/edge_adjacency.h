// Which faces share an edge: the neighbourhood the charts grow over (paper section 4.5).
//
// Half-edges are bucket-sorted by their smaller vertex, then by the larger one inside each
// (small) bucket: linear time, flat arrays, no hashing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

constexpr uint32_t kNoOpposite = UINT32_MAX;

struct EdgeAdjacency {
    // For half-edge h = 3f + i (corner i to corner (i+1)%3 of face f): the half-edge of the one
    // other face on the same edge, or kNoOpposite on a border edge, a non-manifold edge (three or
    // more faces: treated as a chart border) or an edge whose two ends are the same vertex.
    std::vector<uint32_t> opposite;
    size_t borderEdges = 0;
    size_t nonManifoldEdges = 0;
};

// Vertex indices must be < vertexCount (validateAtlasMesh).
EdgeAdjacency buildEdgeAdjacency(const uint32_t *triangles, size_t faceCount, size_t vertexCount);

// The triangles with every vertex replaced by the first vertex at exactly the same position:
// the adjacency of a mesh stored without shared vertices (one copy per corner, as STL files
// and some exporters write them).
std::vector<uint32_t> weldByPosition(const glm::vec3 *positions, size_t vertexCount, const uint32_t *triangles,
                                     size_t faceCount);

}  // namespace voxelfair
