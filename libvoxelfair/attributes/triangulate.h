// Section 4.4 starts by converting the quads into triangles. Like the authors (doc/method.md §5),
// every polygon is split along fixed diagonals: a fan from its first vertex, so a quad (a,b,c,d)
// becomes (a,b,c) and (a,c,d). A map triangle -> polygon carries the face attributes over.
#pragma once

#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

namespace voxelfair {

// Triangles the fan produces: the sum of (arity - 2) over polygons of 3 or more vertices.
// Offsets must be valid (validatePolygons).
size_t countFanTriangles(const PolygonMesh &mesh);

// Writes 3 indices per triangle to `triangles` and, when non-null, the polygon of each triangle
// to `triangleToPolygon`; both sized by countFanTriangles(). Winding is kept. Polygons of fewer
// than 3 vertices yield nothing. Throws MeshError on invalid polygons, before writing anything.
void triangulatePolygons(const PolygonMesh &mesh, uint32_t *triangles, uint32_t *triangleToPolygon);

}  // namespace voxelfair
