#include "atlas/chart_outline.h"

#include "atlas/chart_runs.h"
#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"
#include "base/short_fill.h"

#include <algorithm>
#include <cmath>
#include <cstring>

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

std::vector<uint8_t> chartSharedEdges(const AtlasCharts &charts, int threads) {
    std::vector<uint8_t> shared;
    if (charts.faceOpposite.size() != 3 * charts.faceCount() || charts.chartFaces.size() != charts.faceCount())
        return shared;
    const size_t faces = charts.faceCount();
    std::vector<uint32_t> position(faces);  // each face's index in chartFaces
    for (size_t i = 0; i < faces; ++i)
        position[charts.chartFaces[i]] = uint32_t(i);
    shared.assign(faces, 0);
    const glm::vec2 *uv = charts.wedgeUv.data();
    const int workers = faces >= kLeastParallelFaces ? bandThreads(threads, faces) : 1;
    const size_t bands = size_t(workers);
    runBands(bands, workers, [&](size_t band) {
        for (size_t i = faces * band / bands; i < faces * (band + 1) / bands; ++i) {
            const uint32_t f = charts.chartFaces[i];
            uint8_t bits = 0;
            for (int k = 0; k < 3; ++k) {
                const uint32_t o = charts.faceOpposite[3 * size_t(f) + size_t(k)];
                if (o == kNoOpposite || charts.faceChart[o / 3] != charts.faceChart[f])
                    continue;
                const size_t j = position[o / 3];
                const uint32_t m = o % 3;
                if (sameBits(uv[3 * i + size_t(k)], uv[3 * j + (m + 1) % 3]) &&
                    sameBits(uv[3 * i + size_t(k + 1) % 3], uv[3 * j + m]))
                    bits = uint8_t(bits | 1 << k);
            }
            shared[i] = bits;
        }
    });
    return shared;
}

bool chartOutline(const AtlasCharts &charts, size_t c, const uint8_t *shared, double scale, glm::dvec2 offset,
                  int height, ChartOutline &out) {
    const size_t first = charts.chartFirstFace[c], count = charts.chartFirstFace[c + 1] - first;
    const glm::vec2 *uv = &charts.wedgeUv[3 * first];
    out.crossings.clear();
    out.corners.resize(3 * count);
    out.rim.assign(count, 0);
    for (size_t t = 0; t < count; ++t) {
        glm::dvec2 *p = &out.corners[3 * t];
        for (int k = 0; k < 3; ++k)  // as rasterizeBlocks computes them, bit for bit
            p[k] = (glm::dvec2(uv[3 * t + size_t(k)]) * scale + offset) * 0.5;
        const double area = doubleArea(p[0], p[1], p[2]);
        if (!(area > 0) || !std::isfinite(area))
            return false;  // clockwise, or not rasterised (raster_detail::setup)
    }
    for (size_t t = 0; t < count; ++t) {
        const uint8_t inner = shared[first + t];
        if (inner == 7)
            continue;
        out.rim[t] = 1;
        for (int k = 0; k < 3; ++k)
            if (!(inner >> k & 1))
                addCrossings(out.corners[3 * t + size_t(k)], out.corners[3 * t + size_t(k + 1) % 3], height,
                             out.crossings);
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
