// A scene's parts meshed as one surface in model space (extractSceneSurface, scene/voxel_scene.h).
#include "scene/voxel_scene.h"

#include "base/parallel_bands.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace voxelfair {

static void appendPart(SceneSurface &out, const BoundarySurface &surface, const PlacedVolume &part,
                       const Palette &palette) {
    // No reserve per part: reserving exactly would reallocate on every part, which makes a scene
    // of many small parts (2^20 instances) quadratic. Growth by doubling stays linear.
    const uint32_t base = uint32_t(out.positions.size());
    for (const glm::vec3 &p : surface.positions)
        out.positions.push_back(glm::vec3(part.toModel * glm::vec4(p, 1.0f)));

    // A mirroring placement turns outward counter-clockwise quads inside out: undo it.
    const bool mirrored = glm::determinant(glm::mat3(part.toModel)) < 0.0f;
    for (size_t q = 0; q < surface.quadCount(); ++q) {
        const uint32_t *c = &surface.quads[4 * q];
        if (mirrored)
            out.quads.insert(out.quads.end(), {base + c[0], base + c[3], base + c[2], base + c[1]});
        else
            out.quads.insert(out.quads.end(), {base + c[0], base + c[1], base + c[2], base + c[3]});
        out.quadColours.push_back(palette.colours[surface.quadVoxels[q].colour]);
        out.quadVoxels.push_back(surface.quadVoxels[q]);
        out.quadParts.push_back(part.part);
    }
    out.partQuadCounts.push_back(surface.quadCount());
    out.stats.cavityVoxelsFilled += surface.stats.cavityVoxelsFilled;
    out.stats.nonManifoldEdgesSplit += surface.stats.nonManifoldEdgesSplit;
    out.stats.nonManifoldVerticesSplit += surface.stats.nonManifoldVerticesSplit;
}

namespace {

// Parts extracted side by side, then appended in order: at most this many kept at once (a
// scene may hold 2^20 small instances).
constexpr size_t kPartWindow = 64;
// A window of fewer voxels than this is extracted on one thread: starting threads would cost more.
constexpr size_t kLeastParallelVoxels = size_t(1) << 14;

bool hasVoxels(const PlacedVolume &part) { return part.volume != nullptr && !part.volume->empty(); }

}  // namespace

SceneSurface extractSceneSurface(const VoxelScene &scene, int threads) {
    SceneSurface out;
    const size_t parts = scene.parts.size();
    std::vector<BoundarySurface> surfaces;
    std::vector<std::exception_ptr> failures;
    for (size_t first = 0; first < parts; first += kPartWindow) {
        const size_t count = std::min(kPartWindow, parts - first);
        size_t voxels = 0, busy = 0;
        for (size_t k = first; k < first + count; ++k)
            if (hasVoxels(scene.parts[k])) {
                voxels += scene.parts[k].volume->voxelCount();
                ++busy;
            }
        surfaces.assign(count, BoundarySurface{});
        failures.assign(count, nullptr);
        const int allThreads =
            voxels >= kLeastParallelVoxels ? bandThreads(threads, std::numeric_limits<size_t>::max()) : 1;
        auto extract = [&](size_t k, int partThreads) {
            const PlacedVolume &part = scene.parts[first + k];
            if (!hasVoxels(part))
                return;
            try {
                surfaces[k] = extractBoundarySurface(*part.volume, partThreads);
            } catch (...) {  // rethrown below, in part order
                failures[k] = std::current_exception();
            }
        };
        // A part holding half the window's voxels or more is meshed in slabs on all threads (the
        // others would wait for it), beside the rest.
        size_t largest = count;
        for (size_t k = 0; k < count && allThreads > 1; ++k)
            if (hasVoxels(scene.parts[first + k]) && 2 * scene.parts[first + k].volume->voxelCount() >= voxels)
                largest = k;
        runBands(count, std::min(allThreads, bandThreads(threads, busy)),
                 [&](size_t k) { extract(k, k == largest ? allThreads : 1); });
        for (size_t k = 0; k < count; ++k) {
            if (failures[k])
                std::rethrow_exception(failures[k]);
            const PlacedVolume &part = scene.parts[first + k];
            if (!hasVoxels(part))
                out.partQuadCounts.push_back(0);
            else
                appendPart(out, surfaces[k], part, scene.palette);
        }
    }
    return out;
}

}  // namespace voxelfair
