// Section 4.4: face normals from the counter-clockwise vertex order (right-hand rule).
#pragma once

#include "fairing/polygon_adjacency.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

// The unit normal of triangle (a, b, c): normalise((b - a) x (c - a)); (0,0,0) when degenerate
// or non-finite, so callers can tell and skip it.
glm::vec3 triangleNormal(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c);

// One unit normal per polygon: the normalised sum of the unit normals of its fan triangles
// (triangulate.h), as the authors did for quads (doc/method.md §5); a planar polygon gets its
// plane's normal. (0,0,0) for polygons with no non-degenerate triangle. On error nothing is written.
PolygonMeshError computePolygonNormals(const glm::vec3 *positions, size_t vertexCount,
                                       const uint32_t *polygonOffsets, const uint32_t *polygonIndices,
                                       size_t polygonCount, glm::vec3 *polygonNormals);

}  // namespace voxelfair
