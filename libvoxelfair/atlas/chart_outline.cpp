#include "atlas/chart_outline.h"

#include "atlas/chart_runs.h"
#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"
#include "base/short_fill.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace voxelfair {
namespace {

// The same float bits (two UVs computed alike for the same vertex): a corner shared exactly.
bool sameBits(const glm::vec2 &a, const glm::vec2 &b) {
    uint32_t p[2], q[2];
    std::memcpy(p, &a.x, 4), std::memcpy(p + 1, &a.y, 4);
    std::memcpy(q, &b.x, 4), std::memcpy(q + 1, &b.y, 4);
    return p[0] == q[0] && p[1] == q[1];
}

// The crossings of edge p -> q with the rows of centres y = row + 0.5 in [0, height): those with y
// in [lower end, upper end), each once; +1 going up, -1 going down.
void addCrossings(glm::dvec2 p, glm::dvec2 q, int height, std::vector<ChartOutline::Crossing> &out) {
    if (p.y == q.y)
        return;  // crosses no row of centres, or runs along one: its rim triangle sets those blocks
    const double low = std::min(p.y, q.y), high = std::max(p.y, q.y);
    const int first = std::max(0, ceilToInt(std::clamp(low - 0.5, -1.0, double(height))));
    const int last = std::min(height - 1, ceilToInt(std::clamp(high - 0.5, -1.0, double(height))) - 1);
    const int32_t winding = q.y > p.y ? 1 : -1;
    const double slope = (q.x - p.x) / (q.y - p.y);
    for (int row = first; row <= last; ++row)
        out.push_back({row, winding, p.x + (row + 0.5 - p.y) * slope});
}

}  // namespace

ChartOutlineBasis chartOutlineBasis(const AtlasCharts &charts, int threads) {
    ChartOutlineBasis basis;
    if (charts.faceOpposite.size() != 3 * charts.faceCount() || charts.chartFaces.size() != charts.faceCount())
        return basis;
    const size_t faces = charts.faceCount(), chartCount = charts.chartCount();
    // Each face's index in chartFaces (a permutation: the bands write apart); an opposite face
    // is in the chart when its index is in the chart's range (no chart of its own to look up).
    std::vector<uint32_t> position(faces);
    basis.shared.resize(faces);
    basis.lo.resize(chartCount);
    basis.hi.resize(chartCount);
    basis.leastArea.resize(chartCount);
    basis.longestSide.resize(chartCount);
    const glm::vec2 *uv = charts.wedgeUv.data();
    const ChartRuns runs = chartRuns(charts, threads);
    runBands(runs.count(), runs.workers, [&](size_t run) {
        for (size_t i = charts.chartFirstFace[runs.from[run]]; i < charts.chartFirstFace[runs.from[run + 1]]; ++i)
            position[charts.chartFaces[i]] = uint32_t(i);
    });
    runBands(runs.count(), runs.workers, [&](size_t run) {
        for (size_t c = runs.from[run]; c < runs.from[run + 1]; ++c) {
            const size_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            glm::vec2 lo(INFINITY), hi(-INFINITY);
            double least = INFINITY, longest = 0;
            bool finite = true;
            for (size_t i = first; i < end; ++i) {
                const glm::vec2 *w = &uv[3 * i];
                const uint32_t *opposite = &charts.faceOpposite[3 * size_t(charts.chartFaces[i])];
                uint8_t bits = 0;
                lo = glm::min(lo, glm::min(w[0], glm::min(w[1], w[2])));
                hi = glm::max(hi, glm::max(w[0], glm::max(w[1], w[2])));
                const glm::dvec2 a = glm::dvec2(w[1]) - glm::dvec2(w[0]), b = glm::dvec2(w[2]) - glm::dvec2(w[0]);
                const glm::dvec2 spans = glm::max(glm::abs(a), glm::max(glm::abs(b), glm::abs(b - a)));
                longest = std::max({longest, spans.x, spans.y});
                const double area = a.x * b.y - a.y * b.x;  // doubleArea of the UVs
                finite = finite && std::isfinite(area);
                least = std::min(least, area);
                for (int k = 0; k < 3; ++k) {
                    if (opposite[k] == kNoOpposite)
                        continue;
                    const size_t j = position[opposite[k] / 3];
                    const uint32_t m = opposite[k] % 3;
                    if (j >= first && j < end && sameBits(w[k], uv[3 * j + (m + 1) % 3]) &&
                        sameBits(w[(k + 1) % 3], uv[3 * j + m]))
                        bits = uint8_t(bits | 1 << k);
                }
                basis.shared[i] = bits;
            }
            basis.lo[c] = lo, basis.hi[c] = hi;
            basis.leastArea[c] = finite && std::isfinite(longest) ? least : NAN;
            basis.longestSide[c] = longest;
        }
    });
    return basis;
}

bool ChartOutlineBasis::certainlyTurnsLeft(size_t c, double scale, double reach) const {
    // Coordinates q = uv * scale + offset, at most M in size, come out within eps M of exact
    // (two roundings of half an epsilon); a side within l of its exact length; the area, exactly
    // scale^2 times the UV area (itself within 3 eps L^2 of leastArea), within about
    // 8 eps M l + 6 eps l^2 of its exact value. Certain when scale^2 leastArea exceeds 8 times all of it.
    constexpr double eps = std::numeric_limits<double>::epsilon();
    const double a = leastArea[c], side = longestSide[c];
    const double size = std::max({std::abs(lo[c].x), std::abs(lo[c].y), std::abs(hi[c].x), std::abs(hi[c].y)});
    const double m = scale * size + reach, l = scale * side + 8 * eps * m;
    return a > 0 && std::isfinite(m) && scale > 0 &&
           scale * scale * a > 64 * eps * (scale * scale * side * side + m * l + l * l);
}

bool chartOutline(const AtlasCharts &charts, size_t c, const ChartOutlineBasis &basis, double scale, glm::dvec2 offset,
                  double reach, int height, ChartOutline &out) {
    const size_t first = charts.chartFirstFace[c], count = charts.chartFirstFace[c + 1] - first;
    const glm::vec2 *uv = &charts.wedgeUv[3 * first];
    const uint8_t *shared = &basis.shared[first];
    out.crossings.clear();
    out.rim.clear();
    out.corners.clear();
    // Uncertain charts have every triangle mapped and tested; certain ones only their rim's.
    const bool certain = basis.certainlyTurnsLeft(c, scale, reach);
    for (size_t t = 0; t < count; ++t) {
        const uint8_t inner = shared[t];
        if (inner == 7 && certain)
            continue;
        glm::dvec2 p[3];
        for (int k = 0; k < 3; ++k)  // as rasterizeBlocks computes them, bit for bit
            p[k] = (glm::dvec2(uv[3 * t + size_t(k)]) * scale + offset) * 0.5;
        if (!certain) {
            const double area = doubleArea(p[0], p[1], p[2]);
            if (!(area > 0) || !std::isfinite(area))
                return false;  // clockwise, or not rasterised (raster_detail::setup)
            if (inner == 7)
                continue;
        }
        out.rim.push_back(uint32_t(t));
        out.corners.insert(out.corners.end(), p, p + 3);
        for (int k = 0; k < 3; ++k)
            if (!(inner >> k & 1))
                addCrossings(p[k], p[(k + 1) % 3], height, out.crossings);
    }
    std::sort(out.crossings.begin(), out.crossings.end(),
              [](const ChartOutline::Crossing &a, const ChartOutline::Crossing &b) {
                  return a.row != b.row ? a.row < b.row : a.x < b.x;
              });
    return true;
}

bool fillInsideOutline(const ChartOutline &outline, int width, int height, uint8_t *bits) {
    bool any = false;
    const std::vector<ChartOutline::Crossing> &crossings = outline.crossings;
    for (size_t i = 0; i < crossings.size();) {
        const int row = crossings[i].row;
        int winding = 0;
        double from = 0;
        for (; i < crossings.size() && crossings[i].row == row; ++i) {
            const double to = crossings[i].x;
            if (winding != 0 && row < height) {
                // Centres x + 0.5 in [from, to].
                const int x0 = std::max(0, ceilToInt(std::clamp(from - 0.5, -1.0, double(width))));
                const int x1 = std::min(width - 1, floorToInt(std::clamp(to - 0.5, -1.0, double(width))));
                if (x0 <= x1) {
                    fillBytes(bits + size_t(row) * size_t(width) + size_t(x0), 1, size_t(x1) - size_t(x0) + 1);
                    any = true;
                }
            }
            winding += crossings[i].winding;
            from = to;
        }
    }
    return any;
}

}  // namespace voxelfair
