// Section 4.4: "the surface normal vector of a vertex is calculated as the mean of the surface
// normal vectors of the faces adjacent to such vertex. This calculation must ignore repetitive
// directions." As the authors coded it (doc/method.md §5): the normalised sum of the DISTINCT
// adjacent face normals. On a voxel surface this makes a vertex normal depend only on which
// directions meet there, not on how many faces share each: the corner of a box gets
// (±1,±1,±1)/sqrt(3) however the faces around it are sized or split into triangles.
#pragma once

#include "mesh/csr_adjacency.h"
#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

struct VertexNormalOptions {
    // Two unit face normals with dot > sameDirection count as one direction. Float rounding of
    // identical lattice normals stays far inside 1e-6; a value above 1 disables the rule
    // (plain mean of all adjacent faces).
    float sameDirection = 1.0f - 1e-6f;
};

// Writes one unit normal per vertex from one unit normal per polygon (face_normals.h). Faces
// with a (0,0,0) normal are ignored; a vertex left with nothing, or whose distinct normals
// cancel, gets (0,0,0). The positions are not used. Throws MeshError on invalid polygons, before
// writing anything.
void computeVertexNormals(const PolygonMesh &mesh, const glm::vec3 *polygonNormals, glm::vec3 *vertexNormals,
                          const VertexNormalOptions &options = {});
// The same with the mesh's vertex polygons already built (buildVertexPolygons(mesh)), for a caller
// that also takes the vertex colours (vertex_colours.h) from them. Throws MeshError when they
// have another vertex count.
void computeVertexNormals(const PolygonMesh &mesh, const CsrAdjacency &polygonsOf, const glm::vec3 *polygonNormals,
                          glm::vec3 *vertexNormals, const VertexNormalOptions &options = {});

}  // namespace voxelfair
