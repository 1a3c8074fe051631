// A voxel model ready for meshing: volumes placed in model space and one palette. Every reader
// produces this (a VXL's sections, a VOX's shape instances), and one surface is built from it.
#pragma once

#include "extraction/boundary_surface.h"
#include "formats/palette.h"
#include "volume/voxel_volume.h"

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace voxelfair {

struct PlacedVolume {
    const VoxelVolume *volume = nullptr;  // not owned: several parts may instance one volume
    glm::mat4 toModel{1.0f};              // voxel space -> model space (affine)
    int part = 0;                         // the section or instance number recorded on each face
    std::string name;
};

struct VoxelScene {
    std::vector<PlacedVolume> parts;
    Palette palette;
};

// The merged boundary surface of every part, in model space.
struct SceneSurface {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> quads;         // 4 per quad, counter-clockwise seen from outside
    std::vector<Rgb> quadColours;        // the palette colour of each quad's voxel
    std::vector<Voxel> quadVoxels;       // the voxel payload (palette and normal indices)
    std::vector<int> quadParts;          // PlacedVolume::part of each quad
    std::vector<size_t> partQuadCounts;  // per entry of VoxelScene::parts
    BoundarySurfaceStats stats;          // summed over parts

    size_t quadCount() const { return quadParts.size(); }
};

// Extracts each part's manifold boundary (extractBoundarySurface), maps it to model space and
// concatenates. A part whose transform mirrors space gets its quads reversed, so every quad
// stays counter-clockwise seen from outside. The parts are extracted side by side on up to
// `threads` threads (0: one per hardware thread), a window of parts at a time, and joined in
// part order: the same surface for any count.
SceneSurface extractSceneSurface(const VoxelScene &scene, int threads = 0);

}  // namespace voxelfair
