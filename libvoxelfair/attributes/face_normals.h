// Section 4.4: face normals from the counter-clockwise vertex order (right-hand rule).
#pragma once

#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

// The unit normal of triangle (a, b, c): normalise((b - a) x (c - a)); (0,0,0) when degenerate
// or non-finite, so callers can tell and skip it.
glm::vec3 triangleNormal(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c);

// One unit normal per polygon: the normalised sum of the unit normals of its fan triangles
// (triangulate.h), as the authors did for quads (doc/method.md §5); a planar polygon gets its
// plane's normal. (0,0,0) for polygons with no non-degenerate triangle. Throws MeshError on an
// invalid mesh (validate()), before writing anything.
void computePolygonNormals(const PolygonMesh &mesh, glm::vec3 *polygonNormals);

}  // namespace voxelfair
