// The exact shape of the larger charts on the 2 x 2 block grid (PackOptions::mipBlocks), for
// the tight packer to reuse the holes inside a chart's rows: a large voxel chart is far from
// convex (on the shared tanks the rows' spans of the charts over 128 faces hold 40% more
// blocks than the charts), and the smaller charts packed after it can sit in those holes.
// This is the per-row free-interval packing of Levy et al. 2002's "Tetris" packer and of
// xatlas's bitmap packer, kept to the charts large enough to gain from it.
//
// A bitmap is the chart's block mask (rasterizeChartMasks on blocks: its conservative texels
// grown by the padding, coarsened to blocks), taken over from the masks. Its row extents are
// the mask's profiles.
#pragma once

#include "atlas/chart_masks.h"
#include "atlas/charts.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxelfair {

struct ChartBitmaps {
    // Per chart: the start of its width x height (coarse) bitmap in `bits`, rows from the
    // bottom, or kNone for charts packed by their extents.
    static constexpr size_t kNone = SIZE_MAX;
    std::vector<size_t> first;
    std::vector<uint8_t> bits;
    // Per chart: the blocks its bitmap sets (0 without one).
    std::vector<size_t> setBlocks;
    bool has(size_t chart) const { return chart < first.size() && first[chart] != kNone; }
    const uint8_t *of(size_t chart) const { return bits.data() + first[chart]; }
};

// Takes the bitmaps of the charts whose block mask covers at least `leastBlocks` blocks from
// the block masks (rasterised on blocks; their bitmaps move here), and lowers
// coarse.totalRowTexels to the blocks the bitmaps' row spans hold.
void takeChartBitmaps(const AtlasCharts &charts, ChartMasks &coarse, int64_t leastBlocks, ChartBitmaps &out);

}  // namespace voxelfair
