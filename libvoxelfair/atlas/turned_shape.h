// The tight packer's view of a chart (pack_tight.h): its mask (chart_masks.h) turned by quarter
// turns, as rows of spans. A row is one span between its leftmost and rightmost texel, or, for a
// chart with a bitmap (chart_bitmaps.h), each run of its set texels, so the holes inside its rows
// are left free for smaller charts (the per-row free intervals of Levy et al. 2002's "Tetris"
// packer). The spans are listed longest first: the longest admits the fewest places, so the
// search tests it first and the others mostly confirm it.
#pragma once

#include "atlas/chart_masks.h"

#include <cstdint>
#include <vector>

namespace voxelfair {

struct ShapeSpan {
    int16_t row, left, length;
};

struct TurnedShape {
    int width = 0, height = 0;
    std::vector<int16_t> left, right;
    std::vector<ShapeSpan> spans;  // longest first, rows in order among equals
    // Per row, its longest span (0: none); and the rows with a span, longest first (as the spans).
    std::vector<int16_t> need;
    std::vector<int16_t> needRows;
    std::vector<ShapeSpan> sorted;  // scratch
    std::vector<int> starts;
};

// The runs of set bytes down each column of a chart's bitmap, which the odd turns read as their
// rows: found once per chart (findColumnRuns) for its turns by 90 and 270 degrees.
struct ColumnRuns {
    struct Run {
        int16_t column, bottom, length;
    };
    std::vector<Run> found, runs;  // column x's: runs[first[x] .. first[x + 1]), lowest first
    std::vector<int> first;
    std::vector<int16_t> start;
    std::vector<uint64_t> below;
};

// The column runs of the w x h bitmap `bits` (1 set, 0 not; rows from the bottom).
void findColumnRuns(const uint8_t *bits, int w, int h, ColumnRuns &out);

// The shape of mask `m` turned by `turns` quarter turns counter-clockwise (turnInMask), or its
// bounding box (`box`); with `bits` (its bitmap, chart_bitmaps.h) by its runs of set texels, the odd
// turns read from `columns` (findColumnRuns of the bitmap) when given.
void turnedShape(const ChartMask &m, const std::vector<int16_t> &profiles, int turns, bool box, const uint8_t *bits,
                 const ColumnRuns *columns, TurnedShape &s);

}  // namespace voxelfair
