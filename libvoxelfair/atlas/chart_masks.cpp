#include "atlas/chart_masks.h"

#include "atlas/texel_raster.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace voxelfair {
namespace {

// Masks take a slightly generous coverage (+1/256 texel) and the bake and the measures a
// slightly strict one (-1/256), so float rounding of the final UVs (~1e-4 texel) can never let
// the bake write a texel outside the packed mask.
constexpr double kMaskMargin = 1.0 / 256;

// out[i] = 1 where any of in[i - r .. i + r] is set (n samples).
void dilateRow(const uint8_t *in, uint8_t *out, int n, int r) {
    int count = 0;
    for (int i = 0; i < std::min(r, n); ++i)
        count += in[i];
    for (int i = 0; i < n; ++i) {
        if (i + r < n)
            count += in[i + r];
        if (i - r - 1 >= 0)
            count -= in[i - r - 1];
        out[i] = count > 0;
    }
}

}  // namespace

bool rasterizeChartMasks(const AtlasCharts &charts, double texelsPerUnit, int padding, int maxSide, ChartMasks &masks) {
    masks.charts.assign(charts.chartCount(), ChartMask{});
    masks.profiles.clear();
    masks.texelsPerUnit = texelsPerUnit;
    masks.padding = padding;
    masks.totalMaskTexels = 0;
    std::vector<uint8_t> bits, grown;
    std::vector<int> columnCount;
    const int border = padding + 1;  // the footprint may reach one texel below its box
    for (size_t c = 0; c < charts.chartCount(); ++c) {
        ChartMask &m = masks.charts[c];
        m.scale = charts.isDegenerate(c) ? 1.0 : texelsPerUnit;
        const glm::dvec2 size = glm::dvec2(charts.chartSize[c]) * m.scale;
        if (!(size.x < maxSide && size.y < maxSide))
            return false;
        const int w = int(std::ceil(size.x)) + 2 * border + 1, h = int(std::ceil(size.y)) + 2 * border + 1;
        bits.assign(size_t(w) * h, 0);
        int bx0 = w, bx1 = -1, by0 = h, by1 = -1;  // the footprint's box
        for (size_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const glm::vec2 *uv = &charts.wedgeUv[3 * i];
            rasterConservativeSpans(
                glm::dvec2(uv[0]) * m.scale + double(border), glm::dvec2(uv[1]) * m.scale + double(border),
                glm::dvec2(uv[2]) * m.scale + double(border), kMaskMargin, w, h, [&](int y, int xl, int xr) {
                    std::memset(&bits[size_t(y) * w + xl], 1, size_t(xr) - size_t(xl) + 1);
                    bx0 = std::min(bx0, xl), bx1 = std::max(bx1, xr);
                    by0 = std::min(by0, y), by1 = std::max(by1, y);
                });
        }
        if (bx1 < 0) {  // nothing rasterised (cannot happen for a chart with area): keep one texel
            bx0 = bx1 = by0 = by1 = border;
            bits[size_t(border) * w + border] = 1;
        }
        for (int y = by0; y <= by1; ++y)
            for (int x = bx0; x <= bx1; ++x)
                m.coveredTexels += bits[size_t(y) * w + x];

        // Square dilation by `padding`, separable: each row, then a running count down the
        // columns (row by row, so memory is read in order). The box grows by `padding`.
        const int x0 = bx0 - padding, x1 = bx1 + padding, y0 = by0 - padding, y1 = by1 + padding;
        if (padding > 0) {
            grown.assign(bits.size(), 0);
            for (int y = by0; y <= by1; ++y)
                dilateRow(&bits[size_t(y) * w + x0], &grown[size_t(y) * w + x0], x1 - x0 + 1, padding);
            columnCount.assign(size_t(w), 0);
            for (int y = y0; y <= y1; ++y) {
                if (y + padding <= by1)
                    for (int x = x0; x <= x1; ++x)
                        columnCount[x] += grown[size_t(y + padding) * w + x];
                if (y - padding - 1 >= by0)
                    for (int x = x0; x <= x1; ++x)
                        columnCount[x] -= grown[size_t(y - padding - 1) * w + x];
                for (int x = x0; x <= x1; ++x)
                    bits[size_t(y) * w + x] = columnCount[x] > 0;
            }
        }
        m.width = x1 - x0 + 1;
        m.height = y1 - y0 + 1;
        if (m.width > maxSide || m.height > maxSide)
            return false;
        m.offset = glm::dvec2(border - x0, border - y0);

        m.profile = masks.profiles.size();
        masks.profiles.resize(m.profile + 2 * size_t(m.width) + 2 * size_t(m.height));
        int16_t *bottom = masks.profiles.data() + m.profile, *top = bottom + m.width;
        int16_t *left = top + m.width, *right = left + m.height;
        std::fill(bottom, bottom + m.width, int16_t(m.height));
        std::fill(top, top + m.width, int16_t(-1));
        std::fill(left, left + m.height, int16_t(m.width));
        std::fill(right, right + m.height, int16_t(-1));
        for (int y = 0; y < m.height; ++y)
            for (int x = 0; x < m.width; ++x)
                if (bits[size_t(y + y0) * w + x + x0]) {
                    ++m.maskTexels;
                    bottom[x] = std::min<int16_t>(bottom[x], int16_t(y));
                    top[x] = int16_t(y);
                    left[y] = std::min<int16_t>(left[y], int16_t(x));
                    right[y] = int16_t(x);
                }
        masks.totalMaskTexels += m.maskTexels;
    }
    return true;
}

}  // namespace voxelfair
