#include "atlas/chart_bitmaps.h"

#include <algorithm>

namespace voxelfair {

void takeChartBitmaps(const AtlasCharts &charts, ChartMasks &coarse, int64_t leastBlocks, ChartBitmaps &out) {
    out.first.assign(charts.chartCount(), ChartBitmaps::kNone);
    out.setBlocks.assign(charts.chartCount(), 0);
    out.bits.clear();
    if (coarse.bitsFirst.size() != charts.chartCount())
        return;  // not rasterised on blocks
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const ChartMask &m = coarse.charts[c];
        if (int64_t(m.width) * m.height < leastBlocks || coarse.bitsFirst[c] == ChartMasks::kNoBits)
            continue;
        out.first[c] = coarse.bitsFirst[c];
        out.setBlocks[c] = coarse.setBlocks[c];
        // The room the packer will take: the bitmap's blocks, not the rows' spans.
        const int16_t *l = m.rowLeft(coarse.profiles), *r = m.rowRight(coarse.profiles);
        size_t spans = 0;
        for (int y = 0; y < m.height; ++y)
            spans += size_t(std::max(0, r[y] - l[y] + 1));
        coarse.totalRowTexels -= spans - out.setBlocks[c];
    }
    out.bits.swap(coarse.bits);
}

}  // namespace voxelfair
