#include "volume/voxel_volume.h"

#include <algorithm>

namespace voxelfair {

const Voxel *VoxelVolume::find(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= sizeX || y >= sizeY || z >= sizeZ)
        return nullptr;
    const size_t c = columnIndex(x, y);
    const VoxelRun *first = runs.data() + columnFirstRun[c];
    const VoxelRun *last = runs.data() + columnFirstRun[c + 1];
    // Columns hold a handful of runs: the first run ending after z decides.
    const VoxelRun *run = std::upper_bound(first, last, z, [](int zz, const VoxelRun &r) { return zz < r.zEnd; });
    if (run == last || z < run->zBegin)
        return nullptr;
    return &voxels[run->firstVoxel + uint32_t(z - run->zBegin)];
}

VoxelVolumeBuilder::VoxelVolumeBuilder(int sizeX, int sizeY, int sizeZ) {
    valid_ = sizeX >= 1 && sizeY >= 1 && sizeZ >= 1 && sizeX <= kMaxVolumeSide && sizeY <= kMaxVolumeSide &&
             sizeZ <= kMaxVolumeSide;
    if (!valid_)
        return;
    volume_.sizeX = sizeX;
    volume_.sizeY = sizeY;
    volume_.sizeZ = sizeZ;
    volume_.columnFirstRun.reserve(size_t(sizeX) * size_t(sizeY) + 1);
    volume_.columnFirstRun.push_back(0);
}

bool VoxelVolumeBuilder::add(int x, int y, int z, Voxel voxel) {
    if (!valid_ || x < 0 || y < 0 || z < 0 || x >= volume_.sizeX || y >= volume_.sizeY || z >= volume_.sizeZ)
        return false;
    const size_t column = volume_.columnIndex(x, y);
    if (hasColumn_ && column < currentColumn_)
        return false;
    if (!hasColumn_ || column > currentColumn_) {
        // Columns up to this one are complete: each starts where the runs so far end.
        while (volume_.columnFirstRun.size() <= column)
            volume_.columnFirstRun.push_back(uint32_t(volume_.runs.size()));
        currentColumn_ = column;
        hasColumn_ = true;
        lastZ_ = -1;
    } else if (z <= lastZ_) {
        return false;
    }
    const uint32_t index = uint32_t(volume_.voxels.size());
    volume_.voxels.push_back(voxel);
    const bool extendsRun = volume_.runs.size() > volume_.columnFirstRun[column] && volume_.runs.back().zEnd == z;
    if (extendsRun)
        ++volume_.runs.back().zEnd;
    else
        volume_.runs.push_back(VoxelRun{uint16_t(z), uint16_t(z + 1), index});
    lastZ_ = z;
    return true;
}

VoxelVolume VoxelVolumeBuilder::finish() {
    if (!valid_)
        return VoxelVolume{};
    const size_t columns = size_t(volume_.sizeX) * size_t(volume_.sizeY);
    while (volume_.columnFirstRun.size() < columns + 1)
        volume_.columnFirstRun.push_back(uint32_t(volume_.runs.size()));
    valid_ = false;
    return std::move(volume_);
}

}  // namespace voxelfair
