// Stage 2 of the atlas (paper section 4.5): place the charts in one square texture at one texel
// density and write the final per-wedge UVs.
//
// Charts are packed as rasterised masks (chart_masks.h) grown by half the gutter, so the gutter
// holds in texels whatever the density. Two packers:
//   * Paper - the authors' guillotine tree over bounding boxes (pack_paper.h), kept as the
//             reference: 27% of a 1024^2 texture covered on a Taubin-smoothed voxel sphere of
//             radius 20 (tools/atlas_report).
//   * Tight - bottom-left fill of the charts' rasterised shapes, holes between charts
//             included, with quarter turns (pack_tight.h): 76% on the same sphere. The default.
//
// Size: with textureSize = 0 the density is texelsPerUnit and the side is the smallest power
// of two holding the charts, at most maxTextureSize; if even that is too small the density is
// lowered until the charts fit (densityReduced). With textureSize > 0 the side is fixed and
// the density is the largest that fits (searched to within 0.5%, 4 to 10 packings): the
// authors' fixed 1024 x 1024 texture, and how packing efficiency is measured.
#pragma once

#include "atlas/chart_masks.h"
#include "atlas/charts.h"

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

enum class PackMode { Paper, Tight };

const char *toString(PackMode mode);

struct PackOptions {
    PackMode mode = PackMode::Tight;
    // Texels per model unit; for meshes in voxel units, texels per voxel edge (pass
    // texelsPerVoxel / voxelSize for scaled models). 4 keeps a smoothed voxel face at about 4 x 4
    // texels, enough for its colour to survive bilinear filtering.
    float texelsPerUnit = 4.0f;
    // 0: derive the side from texelsPerUnit (above). > 0: this exact side, densest fit.
    int textureSize = 0;
    // Largest side when textureSize = 0, rounded down to a power of two, at most 16384.
    int maxTextureSize = 4096;
    // Empty texels kept between any two charts; charts also stay gutter/2 texels from the
    // texture's edges, so GL_REPEAT sees the same gap across the seam. The bake fills half of it
    // on each side (BakeOptions::dilation), which keeps bilinear filtering and the first mip
    // level from mixing a chart with the background: level 0 needs 1 texel, level 1 needs 2.
    // Deeper mip levels need 8 (4 rings; 68% instead of 76% on the reference sphere). Rounded
    // up to even, at least 2.
    int gutter = 4;
    // Tight mode: also try each chart turned by 90, 180 and 270 degrees.
    bool allowRotation = true;
};

struct AtlasLayout {
    AtlasStatus status = AtlasStatus::Ok;
    std::string message;  // the error, or with Ok why the density was lowered

    PackMode mode = PackMode::Tight;
    int size = 0;               // the texture is size x size texels
    double texelsPerUnit = 0;   // the density used, identical for every chart
    bool densityReduced = false;
    int gutter = 0;             // as used (even)
    // Three per face, in [0, 1]^2 with v up (OpenGL / OBJ convention): texel (x, y) of the
    // size x size texture covers [x, x+1]/size x [y, y+1]/size.
    std::vector<glm::vec2> wedgeUv;
    std::vector<ChartPlacement> placements;  // per chart, in texels
    size_t packAttempts = 0;     // packings tried while searching the density
    size_t nudgedFaces = 0;      // slivers whose float UVs had lost their area, given 1/64 texel back
};

AtlasLayout packCharts(const AtlasCharts &charts, const PackOptions &options = {});

}  // namespace voxelfair
