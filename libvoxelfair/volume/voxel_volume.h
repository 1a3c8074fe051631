// A voxel model in column-compressed form, shared by every reader and by the surface extraction.
//
// Each (x, y) column holds its solid runs along z, exactly like the spans of a Westwood VXL
// section. Memory grows with the number of solid voxels and runs (plus one index per column),
// not with the volume of the bounding box: a 255^3 box holding a thin shell stays small.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxelfair {

// Payload of one solid voxel: a palette index and, for VXL, an index into the lighting-normal
// table (0 where the format has none).
struct Voxel {
    uint8_t colour = 0;
    uint8_t normal = 0;
};

// Solid voxels z in [zBegin, zEnd) of one column; voxel z is volume.voxels[firstVoxel + z - zBegin].
struct VoxelRun {
    uint16_t zBegin = 0;
    uint16_t zEnd = 0;
    uint32_t firstVoxel = 0;
};

// Largest accepted side, in voxels. VXL stores sizes in a byte (255) and MagicaVoxel caps models
// at 256; 2048 leaves room for other tools while bounding the per-column index
// (2048 * 2048 columns * 4 bytes = 16 MiB) that a hostile header could otherwise inflate.
constexpr int kMaxVolumeSide = 2048;

struct VoxelVolume {
    int sizeX = 0;
    int sizeY = 0;
    int sizeZ = 0;
    // Column (x, y) owns runs[columnFirstRun[c] .. columnFirstRun[c + 1]) with c = y * sizeX + x
    // (x fastest, the VXL column order). Runs of a column are sorted, disjoint and never touch:
    // touching runs are merged.
    std::vector<uint32_t> columnFirstRun;
    std::vector<VoxelRun> runs;
    std::vector<Voxel> voxels;

    size_t voxelCount() const { return voxels.size(); }
    bool empty() const { return voxels.empty(); }
    size_t columnIndex(int x, int y) const { return size_t(y) * size_t(sizeX) + size_t(x); }

    // The voxel at (x, y, z), or nullptr when it is empty or outside the volume.
    const Voxel *find(int x, int y, int z) const;
    bool solid(int x, int y, int z) const { return find(x, y, z) != nullptr; }
};

// Builds a VoxelVolume from voxels given column by column in VXL order (column index
// y * sizeX + x non-decreasing) and, inside a column, by increasing z. Both readers deliver voxels
// this way (the VOX reader sorts its sparse list first), so building is a single linear pass.
class VoxelVolumeBuilder {
public:
    // Sides must be in [1, kMaxVolumeSide]; otherwise valid() is false and nothing is allocated.
    VoxelVolumeBuilder(int sizeX, int sizeY, int sizeZ);

    bool valid() const { return valid_; }

    // Returns false (and adds nothing) when (x, y, z) is outside the volume or not after the
    // previously added voxel in the order above; the caller turns that into a format error.
    bool add(int x, int y, int z, Voxel voxel);

    // Closes the remaining columns and hands the volume over; the builder is empty afterwards.
    VoxelVolume finish();

private:
    VoxelVolume volume_;
    bool valid_ = false;
    bool hasColumn_ = false;
    size_t currentColumn_ = 0;
    int lastZ_ = -1;
};

}  // namespace voxelfair
