#include "atlas/chart_bitmaps.h"

#include "base/parallel_bands.h"
#include "base/short_fill.h"

#include <algorithm>

namespace voxelfair {

void rasterizeChartBitmaps(const AtlasCharts &charts, ChartMasks &coarse, int64_t leastBlocks, ChartBitmaps &out,
                           int threads) {
    out.first.assign(charts.chartCount(), ChartBitmaps::kNone);
    out.setBlocks.assign(charts.chartCount(), 0);
    out.bits.clear();
    // Which charts get one and where: then each is built on its own, on any thread.
    std::vector<uint32_t> chosen;
    size_t total = 0;
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const ChartMask &m = coarse.charts[c];
        if (int64_t(m.width) * m.height < leastBlocks || coarse.spanFirst.size() != charts.chartCount() + 1 ||
            coarse.spanFirst[c] == coarse.spanFirst[c + 1])
            continue;
        chosen.push_back(uint32_t(c));
        out.first[c] = total;
        total += size_t(m.width) * size_t(m.height);
    }
    out.bits.assign(total, 0);
    std::vector<size_t> spansOf(chosen.size(), 0);  // blocks in the coarse mask's row spans
    const size_t bands = std::min<size_t>(chosen.size(), 64);
    // Small work stays on one thread: starting threads would cost more.
    runBands(bands, total >= (size_t(1) << 15) ? bandThreads(threads, bands) : 1, [&](size_t band) {
        for (size_t k = band; k < chosen.size(); k += bands) {
            const size_t c = chosen[k];
            const ChartMask &m = coarse.charts[c];
            // The block spans, padding included (rasterizeChartMasks on blocks).
            uint8_t *bits = out.bits.data() + out.first[c];
            for (size_t i = coarse.spanFirst[c]; i < coarse.spanFirst[c + 1]; i += 3) {
                uint8_t *row = bits + size_t(coarse.spans[i]) * size_t(m.width);
                fillBytes(row + coarse.spans[i + 1], 1, size_t(coarse.spans[i + 2]) + 1 - size_t(coarse.spans[i + 1]));
            }
            // The room the packer will take: the bitmap's blocks, not the rows' spans.
            const int16_t *l = m.rowLeft(coarse.profiles), *r = m.rowRight(coarse.profiles);
            size_t spans = 0, set = 0;
            for (int y = 0; y < m.height; ++y) {
                spans += size_t(std::max(0, r[y] - l[y] + 1));
                for (int x = 0; x < m.width; ++x)
                    set += bits[size_t(y) * m.width + x];
            }
            spansOf[k] = spans;
            out.setBlocks[c] = set;
        }
    });
    for (size_t k = 0; k < chosen.size(); ++k)
        coarse.totalRowTexels -= spansOf[k] - out.setBlocks[chosen[k]];
}

}  // namespace voxelfair
