#include "atlas/chart_masks.h"

#include "atlas/chart_outline.h"
#include "atlas/chart_runs.h"
#include "atlas/texel_raster.h"
#include "base/byte_words.h"
#include "base/parallel_bands.h"
#include "base/short_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace voxelfair {
namespace {

// Masks take a slightly generous coverage (+1/256 texel) and the bake and the measures a
// slightly strict one (-1/256), so float rounding of the final UVs (~1e-4 texel) can never let
// the bake write a texel outside the packed mask.
constexpr double kMaskMargin = 1.0 / 256;

constexpr int kNone = std::numeric_limits<int>::max();

// Charts of fewer triangles are rasterised whole: their outline would cost about as much.
constexpr size_t kLeastOutlinedFaces = 16;

// out[k] = the least of v[from + k - r .. from + k + r] (indices outside v left out), kNone
// when all are kNone, for k in [0, count).
void windowMin(const std::vector<int> &v, int from, int count, int r, int *out) {
    const int n = int(v.size());
    for (int k = 0; k < count; ++k) {
        int best = kNone;
        for (int j = std::max(0, from + k - r); j <= std::min(n - 1, from + k + r); ++j)
            best = std::min(best, v[size_t(j)]);
        out[k] = best;
    }
}

// Charts rasterised by one band (rasterizeChartMasks): their profiles and, on blocks, their
// bitmaps (bitsFirst counted from the band's own start).
struct MaskPart {
    std::vector<int16_t> profiles;
    std::vector<uint8_t> bits;
    std::vector<size_t> bitsFirst, setBlocks;
    size_t totalRowTexels = 0;
    std::vector<uint64_t> seen;  // scratch: the columns seen so far in a pass over a bitmap's rows
    ChartOutline outline;        // scratch: the chart's outline
};

// Folds a chart's conservative span (y, xl..xr) into the mask's row and column extents.
struct SpanRecorder {
    std::vector<int> &rowLeft, &rowRight, &colBottom, &colTop;
    void operator()(int y, int xl, int xr) const {
        rowLeft[size_t(y)] = std::min(rowLeft[size_t(y)], xl);
        rowRight[size_t(y)] = std::max(rowRight[size_t(y)], xr);
        int *bottom = colBottom.data(), *top = colTop.data();
        for (int x = xl; x <= xr; ++x) {
            bottom[x] = std::min(bottom[x], y);
            top[x] = std::max(top[x], y);
        }
    }
};

// Chart c straight onto 2 x 2 blocks: the coarse mask that rasterising its texels (on the w x h
// canvas, at `origin`), growing them by `padding` and coarsening would give. The texel mask's
// box is the footprint's, known from the triangles' extents (each triangle's first and last
// texel rows and columns hold its extreme corners), grown by padding; a block is set when a
// texel of it lies within padding of a texel the triangle's grown square meets, i.e. when the
// triangle meets the block grown by padding + kMaskMargin texels: a conservative test on the
// block grid with that margin in blocks. Its three half-plane tests may keep a block near a
// sharp corner that the texel mask leaves out (a superset: still never overlapped by the bake).
//
// The blocks are set in a bitmap (appended to part.bits), the union of the triangles' spans.
// A triangle's spans lie in its conservative box (raster_detail::conservativeBox); the rows of
// the box whose blocks are all set already would add nothing, so only the rows from the first
// to the last row with an unset block are rasterised (the same spans there: rowFrom, rowTo),
// none when every row is set. The extents are then read off the bitmap.
bool rasterizeBlocks(const AtlasCharts &charts, const ChartOutlineBasis *basis, size_t c, double origin, int w, int h,
                     int padding, int maxSide, ChartMask &m, MaskPart &part) {
    // The box of the triangles with area, at uv * scale + origin. The offsets below stay within
    // `reach` of zero (the box lies in the w x h canvas).
    auto map = [&](glm::vec2 uv) { return glm::dvec2(uv) * m.scale + origin; };
    const double reach = origin + padding + std::max(w, h);
    double lx = INFINITY, hx = -INFINITY, ly = INFINITY, hy = -INFINITY;
    if (basis != nullptr && basis->certainlyTurnsLeft(c, m.scale, reach)) {
        // Every triangle has area: the box of all corners, the mapped UV box (map is monotonic).
        const glm::dvec2 lo = map(basis->lo[c]), hi = map(basis->hi[c]);
        lx = lo.x, ly = lo.y, hx = hi.x, hy = hi.y;
    } else {
        for (size_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const glm::vec2 *uv = &charts.wedgeUv[3 * i];
            const glm::dvec2 a = map(uv[0]), b = map(uv[1]), d = map(uv[2]);
            const double area = doubleArea(a, b, d);
            if (!(area != 0) || !std::isfinite(area))
                continue;  // not rasterised (texel_raster.h)
            lx = std::min({lx, a.x, b.x, d.x}), hx = std::max({hx, a.x, b.x, d.x});
            ly = std::min({ly, a.y, b.y, d.y}), hy = std::max({hy, a.y, b.y, d.y});
        }
    }
    int bx0 = padding + 1, bx1 = bx0, by0 = bx0, by1 = bx0;  // nothing with area: keep one texel
    if (lx <= hx) {
        bx0 = clampToInt(std::ceil(lx - 1 - kMaskMargin), 0, w);
        bx1 = clampToInt(std::floor(hx + kMaskMargin), -1, w - 1);
        by0 = clampToInt(std::ceil(ly - 1 - kMaskMargin), 0, h);
        by1 = clampToInt(std::floor(hy + kMaskMargin), -1, h - 1);
    }
    const int x0 = bx0 - padding, y0 = by0 - padding;
    const int texelWidth = bx1 + padding - x0 + 1, texelHeight = by1 + padding - y0 + 1;
    if (texelWidth > maxSide || texelHeight > maxSide)
        return false;
    m.offset = glm::dvec2(origin - x0, origin - y0);
    m.width = (texelWidth + 1) / 2;
    m.height = (texelHeight + 1) / 2;
    const int width = m.width, height = m.height;
    const size_t first = part.bits.size();
    part.bits.resize(first + size_t(width) * size_t(height), 0);
    uint8_t *bits = part.bits.data() + first;
    const double margin = (padding + kMaskMargin) / 2;
    // A chart of more than a few triangles: the blocks whose centre lies inside it filled from its
    // outline, then only its rim triangles rasterised (chart_outline.h).
    const size_t faceFirst = charts.chartFirstFace[c], faces = charts.chartFirstFace[c + 1] - faceFirst;
    ChartOutline &outline = part.outline;
    const bool outlined = basis != nullptr && faces >= kLeastOutlinedFaces &&
                          chartOutline(charts, c, *basis, m.scale, m.offset, reach, height, outline);
    bool any = outlined && fillInsideOutline(outline, width, height, bits);
    const size_t rasterised = outlined ? outline.rim.size() : faces;
    for (size_t r = 0; r < rasterised; ++r) {
        // In block units; an outlined chart's rim triangles' were computed with its outline.
        const size_t i = faceFirst + (outlined ? outline.rim[r] : r);
        glm::dvec2 corners[3];
        const glm::dvec2 *p = corners;
        if (outlined) {
            p = &outline.corners[3 * r];
        } else {
            for (int k = 0; k < 3; ++k)
                corners[k] = (glm::dvec2(charts.wedgeUv[3 * i + size_t(k)]) * m.scale + m.offset) * 0.5;
        }
        const glm::dvec2 a = p[0], b = p[1], d = p[2];
        const raster_detail::TexelBox box =
            raster_detail::conservativeBox(std::min({a.x, b.x, d.x}), std::max({a.x, b.x, d.x}),
                                           std::min({a.y, b.y, d.y}), std::max({a.y, b.y, d.y}), margin, width, height);
        if (box.x0 > box.x1 || box.y0 > box.y1)
            continue;
        int first = box.y0, last = box.y1;
        if (any)
            unsetRowRange([&](int y) { return bits + size_t(y) * size_t(width) + size_t(box.x0); },
                          size_t(box.x1) - size_t(box.x0) + 1, box.y0, box.y1, first, last);
        if (first > last)
            continue;
        rasterConservativeSpans(
            a, b, d, margin, width, height,
            [&](int y, int xl, int xr) {
                any = true;
                fillBytes(bits + size_t(y) * size_t(width) + size_t(xl), 1, size_t(xr) - size_t(xl) + 1);
            },
            first, last);
    }
    m.profile = part.profiles.size();
    part.profiles.resize(m.profile + 2 * size_t(width) + 2 * size_t(height));
    int16_t *bottom = part.profiles.data() + m.profile, *top = bottom + width;
    int16_t *left = top + width, *right = left + height;
    if (!any) {  // the one texel and its padding: the whole mask, without a bitmap
        part.bits.resize(first);
        part.bitsFirst.push_back(ChartMasks::kNoBits);
        part.setBlocks.push_back(0);
        std::fill(left, left + height, int16_t(0));
        std::fill(right, right + height, int16_t(width - 1));
        std::fill(bottom, bottom + width, int16_t(0));
        std::fill(top, top + width, int16_t(height - 1));
        part.totalRowTexels += size_t(width) * size_t(height);
        return true;
    }
    // Each row's first and last set block; each column's lowest and highest: the rows where it
    // is first seen going up, then going down. Eight blocks (bytes of 0 or 1) at a time.
    std::fill(bottom, bottom + width, int16_t(height));
    std::fill(top, top + width, int16_t(-1));
    const size_t words = (size_t(width) + 7) / 8;
    auto load = [&](int y, size_t k) { return byteWord(bits + size_t(y) * size_t(width), size_t(width), k); };
    // The bytes of `fresh` (columns 8k + byte) not seen before in the pass: their extent is row y.
    auto note = [](uint64_t fresh, size_t k, int16_t y, int16_t *extent) {
        for (; fresh != 0; fresh &= fresh - 1)
            extent[8 * k + size_t(lowestSetByte(fresh))] = y;
    };
    std::vector<uint64_t> &seen = part.seen;
    seen.assign(words, 0);
    size_t set = 0, columns = 0;
    for (int y = 0; y < height; ++y) {
        int l = -1, r = -1;
        for (size_t k = 0; k < words; ++k) {
            const uint64_t v = load(y, k);
            if (v == 0)
                continue;
            set += setByteCount(v);
            if (l < 0)
                l = int(8 * k) + lowestSetByte(v);
            r = int(8 * k) + highestSetByte(v);
            const uint64_t fresh = v & ~seen[k];
            seen[k] |= v;
            columns += setByteCount(fresh);
            note(fresh, k, int16_t(y), bottom);
        }
        left[y] = int16_t(l >= 0 ? l : width);
        right[y] = int16_t(r);
        if (l >= 0)
            part.totalRowTexels += size_t(r - l + 1);
    }
    seen.assign(words, 0);
    for (int y = height - 1; y >= 0 && columns > 0; --y)
        for (size_t k = 0; k < words; ++k) {
            const uint64_t v = load(y, k), fresh = v & ~seen[k];
            if (fresh == 0)
                continue;
            seen[k] |= v;
            columns -= setByteCount(fresh);
            note(fresh, k, int16_t(y), top);
        }
    part.bitsFirst.push_back(first);
    part.setBlocks.push_back(set);
    return true;
}

// Charts [first, end) into `part` (profiles and bitmaps counted from its own start) and
// masks[first, end): false as soon as one is too large.
bool rasterizeRange(const AtlasCharts &charts, const ChartOutlineBasis *basis, size_t first, size_t end,
                    double texelsPerUnit, int padding, int maxSide, bool onBlocks, ChartMask *masks, MaskPart &part) {
    // The footprint's extent per row (leftmost, rightmost column) and per column (lowest,
    // highest row) in the chart's canvas; kNone where nothing is set. Only these extents reach
    // the packers, so the footprint itself is never stored: the square dilation by `padding`
    // turns into a sliding minimum (maximum) of the extents over 2 * padding + 1 rows (columns).
    std::vector<int> rowLeft, rowRight, colBottom, colTop, grown;
    const int border = padding + 1;  // the footprint may reach one texel below its box
    // A chart's box starts at its UV origin: placed on a texel boundary, the generous margin would
    // reach the texel row and column before it. Just past the margin it starts in its first texel.
    const double origin = border + 2 * kMaskMargin;
    const SpanRecorder record{rowLeft, rowRight, colBottom, colTop};
    for (size_t c = first; c < end; ++c) {
        ChartMask &m = masks[c];
        m.scale = charts.isDegenerate(c) ? 1.0 : texelsPerUnit;
        const glm::dvec2 size = glm::dvec2(charts.chartSize[c]) * m.scale;
        if (!(size.x < maxSide && size.y < maxSide))
            return false;
        const int w = int(std::ceil(size.x)) + 2 * border + 1, h = int(std::ceil(size.y)) + 2 * border + 1;
        if (onBlocks) {
            if (!rasterizeBlocks(charts, basis, c, origin, w, h, padding, maxSide, m, part))
                return false;
            continue;
        }
        rowLeft.assign(size_t(h), kNone);
        rowRight.assign(size_t(h), -kNone);
        colBottom.assign(size_t(w), kNone);
        colTop.assign(size_t(w), -kNone);
        for (size_t i = charts.chartFirstFace[c]; i < charts.chartFirstFace[c + 1]; ++i) {
            const glm::vec2 *uv = &charts.wedgeUv[3 * i];
            rasterConservativeSpans(glm::dvec2(uv[0]) * m.scale + origin, glm::dvec2(uv[1]) * m.scale + origin,
                                    glm::dvec2(uv[2]) * m.scale + origin, kMaskMargin, w, h, record);
        }
        int bx0 = w, bx1 = -1, by0 = h, by1 = -1;  // the footprint's box
        for (int y = 0; y < h; ++y)
            if (rowLeft[size_t(y)] != kNone) {
                by0 = std::min(by0, y), by1 = y;
                bx0 = std::min(bx0, rowLeft[size_t(y)]), bx1 = std::max(bx1, rowRight[size_t(y)]);
            }
        if (bx1 < 0) {  // nothing rasterised (cannot happen for a chart with area): keep one texel
            bx0 = bx1 = by0 = by1 = border;
            rowLeft[size_t(border)] = rowRight[size_t(border)] = border;
            colBottom[size_t(border)] = colTop[size_t(border)] = border;
        }

        // The box grows by `padding`; so does every extent.
        const int x0 = bx0 - padding, x1 = bx1 + padding, y0 = by0 - padding, y1 = by1 + padding;
        m.width = x1 - x0 + 1;
        m.height = y1 - y0 + 1;
        if (m.width > maxSide || m.height > maxSide)
            return false;
        m.offset = glm::dvec2(origin - x0, origin - y0);

        m.profile = part.profiles.size();
        part.profiles.resize(m.profile + 2 * size_t(m.width) + 2 * size_t(m.height));
        int16_t *bottom = part.profiles.data() + m.profile, *top = bottom + m.width;
        int16_t *left = top + m.width, *right = left + m.height;
        // The dilated mask's extent on a line is the footprint's over the 2 * padding + 1 lines
        // around it, widened by padding; maxima are taken as minima of the negations.
        for (int &v : rowRight)
            v = -v;
        for (int &v : colTop)
            v = -v;
        grown.resize(size_t(std::max(m.width, m.height)));
        auto extents = [&](const std::vector<int> &lo, const std::vector<int> &hiNegated, int from, int count,
                           int shift, int emptyLo, int16_t *outLo, int16_t *outHi) {
            int64_t texels = 0;
            windowMin(lo, from, count, padding, grown.data());
            for (int k = 0; k < count; ++k)
                outLo[k] = int16_t(grown[size_t(k)] == kNone ? emptyLo : grown[size_t(k)] - padding - shift);
            windowMin(hiNegated, from, count, padding, grown.data());
            for (int k = 0; k < count; ++k) {
                outHi[k] = int16_t(grown[size_t(k)] == kNone ? -1 : -grown[size_t(k)] + padding - shift);
                texels += std::max(0, outHi[k] - outLo[k] + 1);
            }
            return texels;
        };
        part.totalRowTexels += size_t(extents(rowLeft, rowRight, y0, m.height, x0, m.width, left, right));
        extents(colBottom, colTop, x0, m.width, y0, m.height, bottom, top);
    }
    return true;
}

}  // namespace

bool rasterizeChartMasks(const AtlasCharts &charts, double texelsPerUnit, int padding, int maxSide, ChartMasks &masks,
                         int threads, bool onBlocks, const ChartOutlineBasis *outlines) {
    masks.bits.clear();
    masks.bitsFirst.clear();
    masks.setBlocks.clear();
    masks.charts.assign(charts.chartCount(), ChartMask{});
    masks.profiles.clear();
    masks.texelsPerUnit = texelsPerUnit;
    masks.padding = padding;
    masks.totalRowTexels = 0;
    // Runs of charts (atlas/chart_runs.h) rasterised apart and joined in order.
    const ChartRuns runs = chartRuns(charts, threads);
    const int workers = runs.workers;
    const size_t bands = runs.count();
    const std::vector<size_t> &from = runs.from;
    std::vector<MaskPart> parts(bands);
    const ChartOutlineBasis *basis =
        onBlocks && outlines != nullptr && outlines->shared.size() == charts.faceCount() ? outlines : nullptr;
    std::vector<uint8_t> fits(bands, 0);
    runBands(bands, workers, [&](size_t b) {
        fits[b] = rasterizeRange(charts, basis, from[b], from[b + 1], texelsPerUnit, padding, maxSide, onBlocks,
                                 masks.charts.data(), parts[b]);
    });
    for (size_t b = 0; b < bands; ++b) {
        if (!fits[b])
            return false;
        MaskPart &part = parts[b];
        const size_t profileBase = masks.profiles.size(), bitsBase = masks.bits.size();
        for (size_t c = from[b]; c < from[b + 1]; ++c)
            masks.charts[c].profile += profileBase;
        for (size_t f : part.bitsFirst)
            masks.bitsFirst.push_back(f == ChartMasks::kNoBits ? f : bitsBase + f);
        masks.setBlocks.insert(masks.setBlocks.end(), part.setBlocks.begin(), part.setBlocks.end());
        masks.totalRowTexels += part.totalRowTexels;
        if (bands == 1) {
            masks.profiles.swap(part.profiles);
            masks.bits.swap(part.bits);
        } else {
            masks.profiles.insert(masks.profiles.end(), part.profiles.begin(), part.profiles.end());
            masks.bits.insert(masks.bits.end(), part.bits.begin(), part.bits.end());
        }
    }
    return true;
}

}  // namespace voxelfair
