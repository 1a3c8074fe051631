#include "atlas/chart_bitmaps.h"

#include "atlas/texel_raster.h"

#include <algorithm>

namespace voxelfair {

void rasterizeChartBitmaps(const AtlasCharts &charts, const ChartMasks &fine, ChartMasks &coarse, int64_t leastBlocks,
                           ChartBitmaps &out) {
    out.first.assign(charts.chartCount(), ChartBitmaps::kNone);
    out.bits.clear();
    std::vector<uint8_t> texels, grown;
    const int pad = fine.padding;
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        const ChartMask &f = fine.charts[c];
        ChartMask &m = coarse.charts[c];
        if (int64_t(m.width) * m.height < leastBlocks)
            continue;
        const int w = f.width, h = f.height;
        texels.assign(size_t(w) * size_t(h), 0);
        for (size_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const glm::vec2 *uv = &charts.wedgeUv[3 * i];
            // The masks' margin (chart_masks.cpp: +1/256 texel), so the bitmap holds every
            // texel the bake may write.
            rasterConservativeSpans(glm::dvec2(uv[0]) * f.scale + f.offset, glm::dvec2(uv[1]) * f.scale + f.offset,
                                    glm::dvec2(uv[2]) * f.scale + f.offset, 1.0 / 256, w, h,
                                    [&](int y, int xl, int xr) {
                                        std::fill(texels.begin() + y * w + xl, texels.begin() + y * w + xr + 1, 1);
                                    });
        }
        // Square dilation by the padding: rows, then columns.
        grown.assign(texels.size(), 0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (texels[size_t(y) * w + x])
                    std::fill(grown.begin() + y * w + std::max(0, x - pad),
                              grown.begin() + y * w + std::min(w - 1, x + pad) + 1, 1);
        texels.assign(texels.size(), 0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (grown[size_t(y) * w + x])
                    for (int v = std::max(0, y - pad); v <= std::min(h - 1, y + pad); ++v)
                        texels[size_t(v) * w + x] = 1;
        out.first[c] = out.bits.size();
        out.bits.resize(out.bits.size() + size_t(m.width) * size_t(m.height), 0);
        uint8_t *bits = out.bits.data() + out.first[c];
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (texels[size_t(y) * w + x])
                    bits[size_t(y / 2) * m.width + x / 2] = 1;
        // The room the packer will take: the bitmap's blocks, not the rows' spans.
        const int16_t *l = m.rowLeft(coarse.profiles), *r = m.rowRight(coarse.profiles);
        size_t spans = 0, set = 0;
        for (int y = 0; y < m.height; ++y) {
            spans += size_t(std::max(0, r[y] - l[y] + 1));
            for (int x = 0; x < m.width; ++x)
                set += bits[size_t(y) * m.width + x];
        }
        coarse.totalRowTexels -= spans - set;
    }
}

}  // namespace voxelfair
