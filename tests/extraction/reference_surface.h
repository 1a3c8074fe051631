// Brute-force expectations for the extraction tests, computed on dense grids independently of
// the run-based code under test.
#pragma once

#include "shapes/dense_grid.h"

#include <array>
#include <cstddef>
#include <set>

namespace voxelfair::test {

// The grid after filling enclosed cavities: a dense 6-connected flood fill of the empty cells
// from a one-voxel padding, as in the paper.
struct ReferenceSolid {
    DenseGrid grid;              // the original voxels and payloads
    std::vector<uint8_t> solid;  // after the fill, indexed like grid
    size_t cavityVoxels = 0;

    bool at(int x, int y, int z) const { return grid.inside(x, y, z) && solid[grid.index(x, y, z)]; }
    size_t count() const;
};

ReferenceSolid referenceSolid(const DenseGrid &grid);

// A boundary face: the solid voxel and the outward direction 2 * axis + (1 if towards +axis).
using Face = std::array<int, 4>;

struct ReferenceSurface {
    std::set<Face> faces;        // solid voxels' faces towards an exterior cell
    size_t solidComponents = 0;  // 6-connected components of the filled solid
    // Euler characteristic of the cube complex on the centres of the solid voxels (voxels, shared
    // faces, edges and lattice points with all cells around solid): the topology of the solid
    // with voxels connected through faces only. It equals solidComponents when the solid has no
    // tunnels (after the fill it has no cavities).
    long long solidEuler = 0;
    size_t fourQuadEdges = 0;  // lattice edges with two diagonal solid cells, two empty
    size_t pinchedEdges = 0;   // of those, the ones whose solid cells join around both ends
    size_t surfacePoints = 0;  // lattice points with solid and empty cells around
    // One vertex per sheet: summed over lattice points, the boundary curves of the solid part of
    // a small sphere around the point (solid octants joined through shared quarter-planes), plus
    // one more at each end of a pinched edge.
    size_t vertices = 0;
};

ReferenceSurface referenceSurface(const ReferenceSolid &solid);

}  // namespace voxelfair::test
