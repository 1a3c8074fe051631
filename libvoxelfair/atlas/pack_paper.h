// The paper's packer (paper §4.5; doc/method.md §6f): a greedy guillotine tree over the charts'
// bounding rectangles.
//
// Two lists order the partitions by width and by height. Each step takes the two narrowest and
// sets them side by side, or the two lowest and stacks them, whichever gives the smaller
// max(width, height) (tie: smaller area); the pair becomes one partition of both lists, the tree
// remembering where each part went. At the end the single partition is made square, the
// charts centred along the shorter side (the 2010 behaviour; the authors' later code stretched
// it to the unit square instead, giving anisotropic texels).
//
// Differences from the paper: the rectangles are the padded chart masks, so the gutter is a
// fixed number of texels instead of 3% of the largest chart, and charts are never turned.
#pragma once

#include "atlas/chart_masks.h"

#include <vector>

namespace voxelfair {

// Returns the side of the square holding all charts; placements lie inside [0, side)^2.
int packPaper(const ChartMasks &masks, std::vector<ChartPlacement> &placements);

}  // namespace voxelfair
