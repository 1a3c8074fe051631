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
//
// `expected` > 0 is a size known from elsewhere (the importer measures each part's voxel on the
// voxel surface, io_vxl): it is returned while at least 5% of the measured edges still have that
// length (within the bin width). Fairing keeps the lattice spacing wherever the surface runs
// straight along an axis (flat faces, bars), but on thin parts the cross-sections shrink into a
// mode of their own: a faired 1-voxel bar has as many edges of 0.46 voxels as of 1, and 7 of the
// 20 shared models faired by the paper's pass have their most common edge at 0.12-0.84 voxels.
// A mesh rescaled since has no edge of the expected length left, and its size is detected as
// without one.
//
// The edges are measured on up to `threads` threads (0: one per hardware thread) on larger
// meshes; the size is the same for any count.
float detectVoxelSize(const PolygonMesh &mesh, float expected = 0.0f, int threads = 1);

}  // namespace voxelfair
