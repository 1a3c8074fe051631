// Beyond the paper: charts that mostly enclose empty room are cut. The paper's growth (section
// 4.5) takes every edge-connected face within the cone of the seed's normal, so a frame of thin
// bars (a window, a fence, a scaffold, a wire cube) becomes one ring-shaped chart whose bounding
// box is nearly all hole, and a long diagonal bar one chart whose box is mostly empty. The tight
// packer (pack_tight.h) puts smaller charts into such holes by their bitmaps, but charts of one
// size cannot nest: a 256-voxel wire cube's six equal rings needed six 2048^2 boxes at 8 texels
// per voxel, so the atlas fell to 2.5 texels per voxel in a 4096^2 texture 1.2% full.
//
// A chart whose faces cover less than `minFill` of its bounding box (in its own projection) is
// cut in two at the middle of the box's longer side (each face going by its UV centroid; by the
// centroids' median where one side would be empty), each side split into its edge-connected
// parts, and each part cut again the same way until it covers at least `minFill` or is a single
// face: a recursive bisection, as a k-d tree cuts space. A square ring becomes its four bars (two
// U's, then bars and corners), a diagonal bar pieces about 2 / minFill of its widths long. The
// pieces keep the chart's axis and their UVs, moved to the origin, so voxel edges stay on texel
// rows and no face's stretch changes; each cut costs a seam.
#pragma once

#include "atlas/charts.h"

#include <cstddef>
#include <cstdint>

namespace voxelfair {

struct ChartSplitOptions {
    // The least share of its bounding box a chart's faces must cover to stay whole; 0 cuts none.
    // Default 1/8: a chart whose box is more than 8 times its area (a ring of bars, a long
    // diagonal). Compact charts, even with holes (a hull side around its hatches: 40-90%), are
    // never cut.
    float minFill = 0.125f;
    // Threads measuring the charts' fill (0: one per hardware thread); the cuts themselves run
    // on one. The same pieces for any count.
    int threads = 1;
};

// Cuts the sparse charts of `charts` (as computeCharts makes them, degenerate charts last and
// left alone); `opposite` is the edge adjacency the charts grew over (edge_adjacency.h). Keeps the
// charts' order (a cut chart's pieces in its place, in the order of their first faces) and each
// piece's faces in the chart's order. Returns the number of charts cut.
size_t splitSparseCharts(const uint32_t *opposite, const ChartSplitOptions &options, AtlasCharts &charts);

}  // namespace voxelfair
