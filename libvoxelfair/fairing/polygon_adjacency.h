// Connectivity of a polygon mesh given as raw arrays, in compressed-row (CSR) form: which
// vertices share a polygon with a vertex (the smoothing neighbourhood of section 4.3), and which
// polygons use a vertex (for the per-vertex attributes of section 4.4).
//
// Polygons are given like xatlas/meshoptimizer index buffers of mixed arity: polygon p uses
// polygonIndices[polygonOffsets[p] .. polygonOffsets[p + 1]), so polygonOffsets holds
// polygonCount + 1 entries and starts at 0.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxelfair {

// Rows of a CSR relation: row v is items[offsets[v] .. offsets[v + 1]).
struct CsrAdjacency {
    std::vector<uint32_t> offsets;  // rowCount + 1 entries (empty when nothing was built)
    std::vector<uint32_t> items;

    size_t rowCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    const uint32_t *begin(size_t row) const { return items.data() + offsets[row]; }
    const uint32_t *end(size_t row) const { return items.data() + offsets[row + 1]; }
    size_t size(size_t row) const { return offsets[row + 1] - offsets[row]; }
};

enum class PolygonMeshError {
    None,
    TooManyVertices,     // vertexCount does not fit the 32-bit indices
    BadOffsets,          // polygonOffsets does not start at 0 or decreases
    MissingArray,        // a null array where polygons need one
    IndexOutOfRange,     // an index >= vertexCount
};

const char *describe(PolygonMeshError error);

// Checks the index buffer: offsets start at 0 and never decrease, every index < vertexCount.
// Null arrays are accepted only with polygonCount == 0.
PolygonMeshError validatePolygons(size_t vertexCount, const uint32_t *polygonOffsets,
                                  const uint32_t *polygonIndices, size_t polygonCount);

// Neighbours of v = every other vertex of every polygon using v (for quads: the 4 edge and the
// quad-diagonal neighbours, 8 on a flat lattice; paper §4.3, doc/method.md §3). Each row is sorted and holds
// no duplicate and never v itself (a polygon that repeats a vertex does not make it its own
// neighbour). On error `out` is left empty.
PolygonMeshError buildVertexNeighbours(size_t vertexCount, const uint32_t *polygonOffsets,
                                       const uint32_t *polygonIndices, size_t polygonCount,
                                       CsrAdjacency &out);

// Polygons of v, in increasing polygon order; a polygon that repeats v is listed once.
PolygonMeshError buildVertexPolygons(size_t vertexCount, const uint32_t *polygonOffsets,
                                     const uint32_t *polygonIndices, size_t polygonCount,
                                     CsrAdjacency &out);

}  // namespace voxelfair
