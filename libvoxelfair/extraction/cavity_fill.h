// Enclosed cavities (section 4.2): empty voxels that the exterior cannot reach through face
// neighbours are part of the solid, so they produce no inner surface.
#pragma once

#include "volume/voxel_volume.h"

#include <cstddef>

namespace voxelfair {

// Returns `volume` with every enclosed empty voxel made solid (payload `fill`), and the number
// of voxels so filled in `filled`. Works on the empty gaps between runs, so time and memory
// follow the run count, not the bounding-box volume.
VoxelVolume fillEnclosedCavities(const VoxelVolume &volume, size_t *filled, Voxel fill = Voxel{});

}  // namespace voxelfair
