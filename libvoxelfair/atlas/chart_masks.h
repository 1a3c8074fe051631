// A chart as the packers see it: its triangles rasterised at the packing density (conservative
// coverage, the texels the bake will write) and grown by `padding` texels on every side
// (a square, Chebyshev, dilation). Two masks placed without overlap therefore keep their
// charts at least 2 * padding empty texels apart: the gutter.
//
// The packers read a mask's extent on each row and column. On texels only those are kept: the
// triangles' row spans give the footprint's extents, and the dilation of a set by a square is,
// per row (column), the extents of the 2 * padding + 1 rows (columns) around it widened by
// padding; no per-texel image is built. On 2 x 2 blocks (below) the mask is a bitmap, which the
// tight packer also reads for the holes inside the larger charts' rows (chart_bitmaps.h).
#pragma once

#include "atlas/charts.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

struct ChartOutlineBasis;  // chart_outline.h

struct ChartMask {
    int width = 0, height = 0;
    // Texel coordinates of the chart inside its mask: wedgeUv * scale + offset, where scale is
    // the density (1 for degenerate charts, whose UVs are already texels).
    double scale = 0;
    glm::dvec2 offset{0.0};
    // Into ChartMasks::profiles: for each column x of the mask its lowest and highest set row,
    // for each row y its leftmost and rightmost set column.
    size_t profile = 0;
    const int16_t *colBottom(const std::vector<int16_t> &p) const { return p.data() + profile; }
    const int16_t *colTop(const std::vector<int16_t> &p) const { return p.data() + profile + width; }
    const int16_t *rowLeft(const std::vector<int16_t> &p) const { return p.data() + profile + 2 * width; }
    const int16_t *rowRight(const std::vector<int16_t> &p) const { return p.data() + profile + 2 * width + height; }
};

struct ChartMasks {
    std::vector<ChartMask> charts;
    std::vector<int16_t> profiles;
    double texelsPerUnit = 0;
    int padding = 0;
    // Texels between the leftmost and rightmost set texel of every row of every mask: no
    // packing of the masks takes less room (the tight packer takes these spans or more).
    size_t totalRowTexels = 0;
    // On blocks: every chart's block mask as a bitmap, width x height bytes (1: set), rows from
    // the bottom, chart c's from bits[bitsFirst[c]], and setBlocks[c] the blocks it sets. A
    // chart none of whose triangles has area is taken whole (its one texel and padding) and
    // has no bitmap: kNoBits, 0 blocks. Empty off blocks.
    static constexpr size_t kNoBits = SIZE_MAX;
    std::vector<uint8_t> bits;
    std::vector<size_t> bitsFirst, setBlocks;
};

// Where a packer put a chart: the mask's lower-left corner in the texture, after turning it by
// quarterTurns * 90 degrees counter-clockwise (turnInMask).
struct ChartPlacement {
    int x = 0, y = 0;
    int quarterTurns = 0;
};

// Rasterises every chart at `texelsPerUnit`. Returns false (and leaves `masks` partial) as soon
// as a mask would be wider or taller than maxSide, which bounds the work for absurd densities.
// On up to `threads` threads (0: one per hardware thread); the masks are the same for any count.
// onBlocks: the masks on a grid of 2 x 2 texel blocks (PackOptions::mipBlocks), rasterised there
// directly: a block is set when any texel of the texel mask is (or, rarely, near a sharp corner,
// one more), so masks placed without overlap at even texels share no block. Sizes, profiles,
// bitmaps and totalRowTexels are then in blocks; scale and offset still map chart points to the
// texel mask's texels, whose size is twice the block mask's (rounded up to even).
// outlines (chart_outline.h's chartOutlineBasis of these charts), on blocks: each chart's
// inside filled from its outline and only its rim triangles rasterised (the same blocks, see
// there); without it every triangle is rasterised.
bool rasterizeChartMasks(const AtlasCharts &charts, double texelsPerUnit, int padding, int maxSide, ChartMasks &masks,
                         int threads = 0, bool onBlocks = false, const ChartOutlineBasis *outlines = nullptr);

// The mask-local texel position of chart point `p` (scaled and offset already) after `quarterTurns`
// counter-clockwise turns of the width x height mask; integer texels map to integer texels.
inline glm::dvec2 turnInMask(glm::dvec2 p, int width, int height, int quarterTurns) {
    switch (quarterTurns & 3) {
    case 1: return {height - p.y, p.x};
    case 2: return {width - p.x, height - p.y};
    case 3: return {p.y, width - p.x};
    default: return p;
    }
}

}  // namespace voxelfair
