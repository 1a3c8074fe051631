// Stage 2 of the atlas (paper section 4.5): place the charts in one square texture at one texel
// density and write the final per-wedge UVs.
//
// Charts are packed as rasterised masks (chart_masks.h) grown by half the gutter, so the gutter
// holds in texels whatever the density; by default (mipBlocks) on aligned 2 x 2 blocks, which
// keeps mip level 1 apart with half the gutter. Two packers:
//   * Paper - the authors' guillotine tree over bounding boxes (pack_paper.h), kept as the
//             reference: 27% of a 1024^2 texture covered on a Taubin-smoothed voxel sphere of
//             radius 20 (tools/atlas_report).
//   * Tight - bottom-left fill of the charts' rasterised shapes, holes between charts
//             included, with quarter turns (pack_tight.h): 76% on the same sphere. The default.
//
// Size, two modes:
//   * density -> texture (textureSize = 0, the default): texelsPerUnit is the least density; the
//     texture is the smallest power of two holding the charts at it, square or 2:1 (s x s/2,
//     width the longer side, allowWide), at most maxTextureSize; then, with fillTexture, the
//     density is raised towards the largest that still fits that texture (at most fillAttempts
//     more packings: first at the density where the charts' room, estimated from the first
//     packing's masks, fills the texture as densely as that packing filled its rows; after a
//     miss, where the first packing's height grown like the density squared reaches 97% of the
//     texture; skipped when it would gain under 4%; after a second miss, the geometric mean of
//     the fit and the lowest miss; models up to 32768 faces go on after a fit, cheapFillFaces;
//     larger ones stop at their first fit and try the second aim first when the first is within
//     3% above it: close aims missed on the larger shared models, and a packing is costly there),
//     so the charts fill it instead of leaving up
//     to three quarters empty after rounding; a small texture whose charts still fill under
//     half of it (rims of few small charts) steps up while small (leastChartShare). If even
//     the largest texture is too small the
//     density is lowered until the charts fit (densityReduced).
//   * texture -> density (textureSize > 0): the side is fixed (textureHeight: a non-square one)
//     and the density is the largest that fits (4 to 10 packings): the authors' fixed
//     1024 x 1024 texture, and how packing efficiency is measured.
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
    // With textureSize > 0: the height, when not square (0: textureSize). Tight packing only.
    int textureHeight = 0;
    // Density mode: allow a 2:1 texture (s x s/2) where the charts fit one. Tight packing only.
    bool allowWide = true;
    // Density mode: raise the density to fill the texture chosen (texelsPerUnit is then a
    // minimum), with at most this many more packings (the second and third only after a miss:
    // 3tnktur's first two aims, 9.6 and 9.4 texels per voxel, miss; the third fits at 8.5, its
    // coverage 50 -> 57%). Tight packing only.
    bool fillTexture = true;
    int fillAttempts = 3;
    // Models of at most cheapFillFaces faces pack in a few milliseconds: their fill packs up to
    // cheapFillExtra more times and goes on halving the bracket after a fit. A larger model whose
    // masks at texelsPerUnit take under 68% of the first texture shape tried is first packed
    // where they would fill 68% of it (below what the packer fills on any larger model seen), not
    // at texelsPerUnit: one packing instead of two on the synthetic tank at 8 texels per voxel.
    int cheapFillFaces = 32768;
    int cheapFillExtra = 2;
    // Density mode with fillTexture, small textures: each chart's rim (padding, blocks) costs
    // texels whatever the density, and on a model of few small charts the smallest texture
    // holding them is mostly rims (12 faces: 5% charts in 16 x 8). While the charts' projected
    // area fills less than this share of the texture, the larger sizes up to smallTexels
    // (512 x 256, 512 KiB) are tried, each at the density that fills it, and the one giving the
    // charts the largest share is kept (a few packings of tiny textures). 0: never.
    double leastChartShare = 0.5;
    int smallTexels = 512 * 256;
    // Where the search for the largest density that fits a fixed size, or the largest texture
    // when the density must be lowered, starts (texels per unit; 0: just below the bound the
    // charts' area sets). The atlas' separation rounds pass the density the last round found:
    // the new charts need a little more room than those it was found for (a 256 x 256 terrain's
    // 800k charts, five searches: 52 -> 40 packings). Tight packing only (the paper packer's
    // square predicts its density in one step).
    double startDensity = 0;
    // Largest side when textureSize = 0, rounded down to a power of two, at most 16384.
    int maxTextureSize = 4096;
    // Empty texels kept between any two charts; charts also stay gutter/2 texels from the
    // texture's edges, so GL_REPEAT sees the same gap across the seam. The bake fills half of it
    // on each side (BakeOptions::dilation), which keeps bilinear filtering and the first mip
    // level from mixing a chart with the background: level 0 needs 1 texel, level 1 needs 2.
    // Deeper mip levels need 8 (4 rings; 68% instead of 76% on the reference sphere). Rounded
    // up to even, at least 2. With mipBlocks, 2 keeps what 4 keeps without them (levels 0 and 1).
    int gutter = 2;
    // Tight packing: place the charts on aligned 2 x 2 texel blocks, each block holding texels of
    // one chart only (masks coarsened to blocks, packed at half resolution, placed at even
    // texels; the bake fills every block a chart touches with that chart's colours). A box
    // filtered mip level 1 texel is then one chart's, and bilinear filtering at level 1 of a
    // point inside a chart reads only the blocks within one texel of it: a 1-texel ring (gutter
    // 2) protects levels 0 and 1, as 2 rings (gutter 4) do on the texel grid, for about 1.5
    // texels less per chart side (the mip-aligned padding of texture atlas practice, e.g.
    // xatlas's blockAlign, here at 2 x 2). Sizes and placements stay in texels.
    bool mipBlocks = true;
    // Tight mode: also try each chart turned by 90, 180 and 270 degrees.
    bool allowRotation = true;
    // Threads rasterising the charts, searching the large charts' turns and writing the final
    // UVs (0: one per hardware thread); the layout is the same for any count.
    int threads = 0;
};

struct AtlasLayout {
    PackMode mode = PackMode::Tight;
    // The texture is width x height texels, width >= height (2:1 at most unless textureHeight
    // asks otherwise). size is the width, kept from when the layout was always square.
    int size = 0;
    int width = 0, height = 0;
    double texelsPerUnit = 0;  // the density used, identical for every chart
    bool densityReduced = false;
    std::string note;  // why the density was lowered, when it was
    int gutter = 0;    // as used (even)
    int block = 1;     // 2: charts placed on aligned 2 x 2 blocks (PackOptions::mipBlocks)
    // Three per face, in [0, 1]^2 with v up (OpenGL / OBJ convention): texel (x, y) of the
    // width x height texture covers [x, x+1]/width x [y, y+1]/height.
    std::vector<glm::vec2> wedgeUv;
    std::vector<ChartPlacement> placements;  // per chart, in texels
    size_t packAttempts = 0;                 // packings (placements) tried while searching the density
    size_t nudgedFaces = 0;                  // slivers whose float UVs had lost their area, given 1/64 texel back
};

// Throws OptionError when texelsPerUnit is not positive and finite (density mode) or the charts fit
// no allowed texture at any density; an empty layout (size 0, no UVs) for charts without faces.
AtlasLayout packCharts(const AtlasCharts &charts, const PackOptions &options = {});

}  // namespace voxelfair
