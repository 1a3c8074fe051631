// The default packer: bottom-left fill of the charts' rasterised shapes on the texel grid
// (the packing of xatlas's brute-force mode and of Levy et al. 2002's "Tetris" family, made
// fast enough for tens of thousands of charts).
//
// Charts go largest first. Each goes to the lowest row, then leftmost column, where its mask
// fits among the charts already placed, holes between them included, trying the four quarter
// turns and keeping the one whose top ends lowest. A chart's row is taken as the span between
// its leftmost and rightmost texel, or with a bitmap (chart_bitmaps.h) as its runs of texels. Charts smaller than 1/1024 of the texture (the paper's
// "micro partitions", thousands on voxel models) go in as their bounding boxes when they have no
// bitmap, which lets the search for each box size resume where the previous one stopped; with a
// bitmap by their shape, the search resumed the same way per turned size (a heuristic there:
// another shape of that size may fit lower), which keeps them about as cheap and packs their
// holes and corners (on the shared models a box held 2-3 times a small chart's area).
#pragma once

#include "atlas/chart_bitmaps.h"
#include "atlas/chart_masks.h"

#include <cstdint>
#include <vector>

namespace voxelfair {

struct TightPacking {
    bool fits = false;
    // Texels the charts take in the atlas (their boxes, or their rows' spans): all of them, and
    // those placed before one did not fit. A packing that misses tells how full it got.
    size_t room = 0;
    size_t placedRoom = 0;
    // On a fit: the rows the charts reach (the highest chart's top). The fill aims from it.
    int top = 0;
};

// Whether packTight places a chart as its bounding box: a mask of `maskArea` texels under 1/1024
// of the side x height rectangle, without a bitmap (the paper's micro partitions, above).
inline bool packedAsBox(int64_t maskArea, int side, int height, bool hasBitmap) {
    return !hasBitmap && maskArea < int64_t(side) * height / 1024;
}

// Packs into a side x height rectangle, side the width (both <= 16383). Charts with a bitmap
// leave the holes inside their rows free. With threads > 1 (0: one per hardware thread) the
// turns of the charts of at least 1/1024 of the rectangle are searched on two threads: the same
// placements for any count.
TightPacking packTight(const ChartMasks &masks, int side, int height, bool allowTurns,
                       std::vector<ChartPlacement> &placements, const ChartBitmaps *bitmaps = nullptr, int threads = 1);

}  // namespace voxelfair
