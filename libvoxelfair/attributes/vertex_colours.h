// Section 4.4: "the color of a vertex v is computed as the mean of the colors of the faces
// adjacent to it."
//
// Uniform weights, one per adjacent polygon (not per triangle, so the fixed a-c diagonal does
// not count a quad twice at a and c). Why not area weights: every voxel face is one sample of
// its voxel's colour and all are equal in voxel space; the area changes after fairing (shrunk
// corner quads, tilted staircase quads) are geometric, and area weights would make colours depend
// on them. The authors weighted by centroid distance (doc/method.md §5), which on the regular
// lattice is uniform too. Colours are averaged as given (no sRGB linearisation), like the authors.
#pragma once

#include "mesh/csr_adjacency.h"
#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec4.hpp>

namespace voxelfair {

// Writes the mean of the adjacent polygons' colours to every vertex ((0,0,0,0) for a vertex no
// polygon uses), from the mesh's polygonColours. Call it on the quads, before triangulation.
// Throws MeshError on invalid polygons or missing colours, before writing anything.
void computeVertexColours(const PolygonMesh &mesh, glm::vec4 *vertexColours);
// The same with the mesh's vertex polygons already built (buildVertexPolygons(mesh)), as
// computeVertexNormals takes them. Throws MeshError when they have another vertex count.
void computeVertexColours(const PolygonMesh &mesh, const CsrAdjacency &polygonsOf, glm::vec4 *vertexColours);

}  // namespace voxelfair
