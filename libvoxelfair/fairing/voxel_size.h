// The voxel size of a voxel-derived polygon mesh, so the fairing (which works in voxel units)
// smooths a scaled model exactly as the unscaled one.
#pragma once

#include "mesh/polygon_mesh.h"

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace voxelfair {

// The dominant polygon edge length: lengths are binned at 1e-3 relative width and the mean of
// the most populated bin is returned (ties: the shorter bin). On a voxel surface every edge is
// one voxel, so this is exact; after smoothing or scaling it stays the typical edge. Polygon
// edges are the consecutive vertex pairs (not the quad diagonals). Only every k-th polygon is
// measured, k chosen for about 65536 edges, so the cost stays bounded on big meshes. Edges of
// zero or non-finite length and indices out of range are ignored; returns 0 when no edge is left.
// Never throws: a mesh with missing arrays gives 0.
float detectVoxelSize(const PolygonMesh &mesh);

}  // namespace voxelfair
