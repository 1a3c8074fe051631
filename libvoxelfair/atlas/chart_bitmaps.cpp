#include "atlas/chart_bitmaps.h"

#include <algorithm>

namespace voxelfair {

void rasterizeChartBitmaps(const AtlasCharts &charts, const ChartMasks &fine, ChartMasks &coarse, int64_t leastBlocks,
                           ChartBitmaps &out) {
    out.first.assign(charts.chartCount(), ChartBitmaps::kNone);
    out.setBlocks.assign(charts.chartCount(), 0);
    out.bits.clear();
    const int pad = fine.padding;
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const ChartMask &f = fine.charts[c];
        ChartMask &m = coarse.charts[c];
        if (int64_t(m.width) * m.height < leastBlocks || fine.spanFirst.size() != charts.chartCount() + 1 ||
            fine.spanFirst[c] == fine.spanFirst[c + 1])
            continue;
        // Straight onto the blocks: the padding's square dilation of a texel span is the span
        // widened by the padding over the rows around it, and a block is set when any texel of
        // it is, so each span sets a run of blocks on one or two block rows.
        const int w = f.width, h = f.height;
        out.first[c] = out.bits.size();
        out.bits.resize(out.bits.size() + size_t(m.width) * size_t(m.height), 0);
        uint8_t *bits = out.bits.data() + out.first[c];
        for (size_t k = fine.spanFirst[c]; k < fine.spanFirst[c + 1]; k += 3) {
            const int y = fine.spans[k], xl = fine.spans[k + 1], xr = fine.spans[k + 2];
            const int x0 = std::max(0, xl - pad) / 2, x1 = std::min(w - 1, xr + pad) / 2;
            const int y1 = std::min(h - 1, y + pad) / 2;
            for (int by = std::max(0, y - pad) / 2; by <= y1; ++by)
                std::fill(bits + size_t(by) * m.width + x0, bits + size_t(by) * m.width + x1 + 1, uint8_t(1));
        }
        // The room the packer will take: the bitmap's blocks, not the rows' spans.
        const int16_t *l = m.rowLeft(coarse.profiles), *r = m.rowRight(coarse.profiles);
        size_t spans = 0, set = 0;
        for (int y = 0; y < m.height; ++y) {
            spans += size_t(std::max(0, r[y] - l[y] + 1));
            for (int x = 0; x < m.width; ++x)
                set += bits[size_t(y) * m.width + x];
        }
        coarse.totalRowTexels -= spans - set;
        out.setBlocks[c] = set;
    }
}

}  // namespace voxelfair
