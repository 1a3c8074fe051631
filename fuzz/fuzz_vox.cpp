// Fuzzes the VOX reader, then what the importer does with an accepted file: place the instances
// of a few frames and mesh them; every part must be a closed, consistently oriented manifold.
#include "formats/format_error.h"
#include "formats/vox.h"
#include "scene/vox_scene.h"
#include "checks/surface_checks.h"

#include <algorithm>

using namespace voxelfair;
using namespace voxelfair::fuzz;

namespace {

// Meshing is skipped above these (the reader's limits allow 2^20 instances and 2^24 voxels,
// seconds of work): the fuzzer should spend its time on many inputs, not on one big scene.
constexpr size_t kMaxMeshedParts = 256;
constexpr size_t kMaxMeshedVoxels = size_t(1) << 16;

void placeAndMesh(const VoxFile &file, int frame) {
    const VoxelScene scene = voxScene(file, VoxSceneOptions{frame});
    size_t voxels = 0;
    for (const PlacedVolume &part : scene.parts) {
        check(part.volume >= file.models.data() && part.volume < file.models.data() + file.models.size(),
              "a part points outside the file's models");
        voxels += part.volume->voxelCount();
    }
    if (scene.parts.size() > kMaxMeshedParts || voxels > kMaxMeshedVoxels)
        return;
    const SceneSurface surface = extractSceneSurface(scene);
    check(surface.partQuadCounts.size() == scene.parts.size(), "a part without its quad count");
    checkClosedManifold(surface.quads, surface.positions.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    VoxFile file;
    try {
        file = readVox(data, size);
    } catch (const FormatError &) {
        return 0;
    }
    check(!file.models.empty() && file.frameCount >= 1, "accepted a file without models or frames");
    // First, middle and last frame: keyframe lookup at both ends and in between.
    for (int frame : {0, file.frameCount / 2, file.frameCount - 1})
        placeAndMesh(file, frame);
    try {
        voxScene(file, VoxSceneOptions{file.frameCount});
        fail("frame %d past the last one was accepted", file.frameCount);
    } catch (const FormatError &) {
    }
    return 0;
}
