// Section 4.2 of the paper: the boundary of a voxel solid as a closed quad mesh, one quad per
// voxel face between a solid voxel and the exterior.
//
// Beyond the paper: the result is always 2-manifold. Where solid voxels touch only along an edge
// or at a corner (the paper's open "topological problem of type 2"), edges and vertices are split
// so that each sheet has its own copies; solid voxels count as connected through faces only.
// One exception: a tunnel pinched to a single lattice edge at both of its ends would need two
// distinct edges between the same two vertices, so there the sheets are joined across the edge
// instead, closing that zero-width tunnel (lattice_vertex_sheets.h).
#pragma once

#include "volume/voxel_volume.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

struct BoundarySurfaceStats {
    size_t cavityVoxelsFilled = 0;     // empty voxels the exterior cannot reach, counted as solid
    size_t nonManifoldEdgesSplit = 0;  // lattice edges shared by four quads, given two copies
    size_t nonManifoldVerticesSplit =
        0;  // lattice points whose quads form several fans, given one copy per fan (extra copies counted)
    size_t pinchedEdgesJoined = 0;  // of those split edges, the ones whose zero-width tunnel was closed (see above)
};

struct BoundarySurface {
    // Lattice corners in the volume's voxel units (integers stored exactly in float). Every
    // vertex is used by a quad; a lattice point has one vertex per sheet through it.
    std::vector<glm::vec3> positions;
    // Four vertex indices per quad, counter-clockwise seen from outside (the normal by the
    // right-hand rule points out of the solid).
    std::vector<uint32_t> quads;
    // The solid voxel each quad bounds (its colour and normal index), one entry per quad.
    std::vector<Voxel> quadVoxels;
    BoundarySurfaceStats stats;

    size_t quadCount() const { return quadVoxels.size(); }
};

// Extracts the manifold boundary surface of `volume`. Enclosed cavities are filled first (no
// quads inside). Runs in time proportional to the number of runs and boundary quads. The corners
// are welded in slabs of the volume on up to `threads` threads (0: one per hardware thread), for
// larger surfaces: the same surface, vertex numbers and quad order for any count.
BoundarySurface extractBoundarySurface(const VoxelVolume &volume, int threads = 1);

}  // namespace voxelfair
