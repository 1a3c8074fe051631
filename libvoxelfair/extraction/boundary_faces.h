// The voxel faces between a solid voxel and an empty cell, read off the column runs (internal to
// the extraction). Called after cavity filling, when every empty cell is exterior.
#pragma once

#include "volume/voxel_volume.h"

#include <cstdint>
#include <vector>

namespace voxelfair {

struct BoundaryFace {
    uint16_t x, y, z;   // the solid voxel
    uint8_t direction;  // outward: 2 * axis + 1 towards +axis, 2 * axis towards -axis
};

// Appends every boundary face of `solid` in rows y0 <= y < y1 and the payload of its voxel,
// column by column (y-major).
void collectBoundaryFaces(const VoxelVolume &solid, int y0, int y1, std::vector<BoundaryFace> &faces,
                          std::vector<Voxel> &voxels);

}  // namespace voxelfair
