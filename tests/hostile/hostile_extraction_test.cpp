// Hostile but valid volumes for the extraction: the most quads per voxel (a checkerboard slab, six
// quads per voxel and every lattice point split) and the largest mostly empty volume. Heap and
// time follow the quads and columns, never the bounding box.
#include "allocation_meter.h"
#include "extraction/boundary_surface.h"
#include "hostile_input.h"

#include <chrono>
#include <cstdio>

using namespace voxelfair;
using namespace voxelfair::test;

namespace {

// Positions, quads, payloads, faces and the lattice-point map: about 105 bytes per quad measured.
constexpr size_t kHeapPerQuad = 160;

VoxelVolume checkerboardSlab(int side) {
    VoxelVolumeBuilder builder(side, side, 1);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            if ((x + y) % 2 == 0)
                builder.add(x, y, 0, Voxel{uint8_t(1 + x % 255), 0});
    return builder.finish();
}

}  // namespace

TEST(HostileExtraction, CheckerboardSlabCostsLinearlyInItsQuads) {
    // 512^2 here to stay quick under the sanitizers; doc/limits.md gives 2048^2 figures.
    for (int side : {256, 512}) {
        const VoxelVolume slab = checkerboardSlab(side);
        const auto start = std::chrono::steady_clock::now();
        AllocationMeter meter;
        const BoundarySurface surface = extractBoundarySurface(slab);
        const size_t peak = meter.peakBytes();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(surface.quadCount(), 6 * slab.voxelCount()) << "every voxel touches the others at edges only";
        EXPECT_EQ(surface.positions.size(), 8 * slab.voxelCount()) << "every corner split per voxel";
        EXPECT_LT(peak, kHeapPerQuad * surface.quadCount());
        EXPECT_LT(seconds, kHangSeconds);
        std::printf("[ hostile  ] %d x %d x 1 checkerboard: %zu quads, %.0f bytes of heap per quad, %.3f s\n", side,
                    side, surface.quadCount(), double(peak) / surface.quadCount(), seconds);
    }
}

TEST(HostileExtraction, LargestVolumeWithOneVoxelCostsItsColumnIndex) {
    VoxelVolumeBuilder builder(kMaxVolumeSide, kMaxVolumeSide, kMaxVolumeSide);
    builder.add(kMaxVolumeSide - 1, kMaxVolumeSide - 1, kMaxVolumeSide - 1, Voxel{1, 0});
    const VoxelVolume volume = builder.finish();
    const size_t columnIndex = volume.columnFirstRun.size() * sizeof(uint32_t);  // 16 MiB
    const auto start = std::chrono::steady_clock::now();
    AllocationMeter meter;
    const BoundarySurface surface = extractBoundarySurface(volume);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(surface.quadCount(), 6u);
    EXPECT_LT(meter.peakBytes(), columnIndex + (1 << 20)) << "at most one copy of the column index";
    EXPECT_LT(seconds, kHangSeconds);
}
