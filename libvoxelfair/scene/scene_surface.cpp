// A scene's parts meshed as one surface in model space (extractSceneSurface, scene/voxel_scene.h).
#include "scene/voxel_scene.h"

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

SceneSurface extractSceneSurface(const VoxelScene &scene) {
    SceneSurface out;
    for (const PlacedVolume &part : scene.parts) {
        if (part.volume == nullptr || part.volume->empty()) {
            out.partQuadCounts.push_back(0);
            continue;
        }
        appendPart(out, extractBoundarySurface(*part.volume), part, scene.palette);
    }
    return out;
}

}  // namespace voxelfair
