// Connectivity of a polygon mesh (polygon_mesh.h) in compressed-row (CSR) form: which vertices
// share a polygon with a vertex (the smoothing neighbourhood of paper §4.3), and which polygons
// use a vertex (for the per-vertex attributes of paper §4.4).
#pragma once

#include "mesh/polygon_mesh.h"

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

// Neighbours of v = every other vertex of every polygon using v (for quads: the 4 edge and the
// quad-diagonal neighbours, 8 on a flat lattice; paper §4.3, doc/method.md §3). Each row is sorted
// and holds no duplicate and never v itself (a polygon that repeats a vertex does not make it its
// own neighbour). `out` is reused (its memory kept) for the next mesh. Throws MeshError on invalid
// polygons (validatePolygons) or more adjacencies than 32-bit offsets hold; `out` is then empty.
// The rows are sorted on up to `threads` threads (0: one per hardware thread): the same rows for
// any count.
void buildVertexNeighbours(const PolygonMesh &mesh, CsrAdjacency &out, int threads = 1);

// Polygons of v, in increasing polygon order; a polygon that repeats v is listed once. Throws
// MeshError like buildVertexNeighbours.
CsrAdjacency buildVertexPolygons(const PolygonMesh &mesh);

}  // namespace voxelfair
