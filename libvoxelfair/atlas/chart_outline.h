// A chart's block mask (chart_masks.h) from its outline: most of its triangles are never
// rasterised.
//
// The mask sets the blocks whose square, grown by the margin, meets one of the chart's triangles
// (the conservative test of texel_raster.h). Such a square either lies inside the chart, and then
// so does the block's centre, or it meets the chart's outline, which runs along edges of its rim
// triangles (those with an edge on the outline). Conversely a centre inside the chart lies in one
// of its triangles, whose test sets that block. So the mask is the rim triangles' blocks plus the
// blocks whose centre lies inside the chart: the rim triangles are rasterised as before and the
// inside is filled row by row from the outline (scanline polygon fill, non-zero winding). On the
// synthetic tank 14% of the triangles are rim triangles, on a smoothed voxel sphere 11%.
//
// The outline: the edges of the chart's triangles, each directed as its triangle runs, except
// those shared with the chart's triangle across them (the mesh's edge adjacency, kept in
// AtlasCharts::faceOpposite) where both meet it at the same two UV corners, bit for bit, running
// the other way. With every triangle counter-clockwise, the winding number of a point about the
// outline is the number of the chart's triangles holding it (each shared pair left out adds 0),
// so it is non-zero exactly inside the chart. Triangles without area (or not finite) in block
// units (the rasteriser leaves them out) would make their neighbours' shared edges outline: a chart
// with such a triangle, or with a clockwise one, has no outline here, and all its triangles are
// rasterised. Which edges are shared does not depend on the density: found once per packing
// (chartOutlineBasis), with what certifies a chart's triangles counter-clockwise at a density
// from its least UV area, so the outline per density costs a pass over its rim triangles only.
//
// The blocks are those of rasterising every triangle except one kind: the three half-plane tests
// of the conservative test also keep a few blocks near a sharp corner of a triangle that its
// grown square does not meet; near an inner triangle's corner those are inside centres or rim
// blocks anyway, and where they are not, the mask leaves out a block that no triangle meets.
#pragma once

#include "atlas/charts.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace voxelfair {

// Reused between charts (one per thread).
struct ChartOutline {
    struct Crossing {
        int32_t row = 0, winding = 0;
        double x = 0;
    };
    std::vector<uint32_t> rim;        // the rim triangles (indices from the chart's first), in order
    std::vector<glm::dvec2> corners;  // theirs in block units, three per rim triangle (rasterizeBlocks reads them)
    std::vector<Crossing> crossings;
};

// What the outlines need that does not depend on the density, measured once per packing.
struct ChartOutlineBasis {
    // Per triangle of charts.chartFaces, bit k set when its edge k (corner k to k + 1) is shared
    // the other way with a triangle of its chart at the same two UV corners, bit for bit.
    std::vector<uint8_t> shared;
    // Per chart: the box of its UV corners; the least double area of its triangles in UV (NaN
    // when a corner is not finite); the longest coordinate difference within one of them.
    std::vector<glm::vec2> lo, hi;
    std::vector<double> leastArea, longestSide;

    bool empty() const { return shared.empty(); }
    // Whether every triangle of chart c, its corners mapped to uv * scale + offset in double
    // arithmetic (each offset component at most `reach` in size; a final halving changes nothing),
    // certainly comes out counter-clockwise with a positive, finite area: a rounding error bound
    // (each mapped coordinate off by under 2 epsilon of its size, areas by the products of those
    // with the sides) with a margin of 8 over it. Then its mapped box is the mapped corners of
    // its UV box (the mapping only rounds monotonically), and no triangle needs testing.
    bool certainlyTurnsLeft(size_t c, double scale, double reach) const;
};

// The basis of the charts' outlines. Empty (no outlines) when the charts have no faceOpposite.
// On up to `threads` threads (0: one per hardware thread).
ChartOutlineBasis chartOutlineBasis(const AtlasCharts &charts, int threads = 0);

// The outline of chart c, in the block units b = (uv * scale + offset) * 0.5 of rasterizeBlocks
// (|offset| components at most `reach`): out.rim lists the triangles to rasterise, with their
// corners, and out.crossings are the outline's crossings of the rows of block centres
// 0..height - 1. False, and nothing usable in `out`, when a triangle of the chart runs clockwise
// or has no area in block units; only a chart the basis cannot certify (certainlyTurnsLeft) has
// all its triangles mapped and tested.
bool chartOutline(const AtlasCharts &charts, size_t c, const ChartOutlineBasis &basis, double scale, glm::dvec2 offset,
                  double reach, int height, ChartOutline &out);

// Sets the blocks of the width x height bitmap (rows from the bottom) whose centre lies inside
// the outline chartOutline found (a centre on it either way: its rim triangle sets that block).
// Returns whether it set any.
bool fillInsideOutline(const ChartOutline &outline, int width, int height, uint8_t *bits);

}  // namespace voxelfair
