// Sparse charts cut by recursive bisection; the contract is in chart_split.h.
#include "atlas/chart_split.h"

#include "atlas/chart_runs.h"
#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/common.hpp>

namespace voxelfair {
namespace {

struct Box {
    glm::vec2 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    double area = 0;  // the faces' projected area
    double fill() const {
        const double box = double(hi.x - lo.x) * double(hi.y - lo.y);
        return box > 0 ? area / box : 1.0;
    }
};

Box boxOf(const AtlasCharts &charts, const std::vector<uint32_t> &entries) {
    Box b;
    for (uint32_t i : entries) {
        const glm::vec2 *uv = &charts.wedgeUv[3 * size_t(i)];
        for (int k = 0; k < 3; ++k)
            b.lo = glm::min(b.lo, uv[k]), b.hi = glm::max(b.hi, uv[k]);
        b.area += 0.5 * std::fabs(doubleArea(uv[0], uv[1], uv[2]));
    }
    return b;
}

}  // namespace

size_t splitSparseCharts(const uint32_t *opposite, const ChartSplitOptions &options, AtlasCharts &charts) {
    if (!(options.minFill > 0) || charts.chartCount() == 0)
        return 0;
    const size_t chartCount = charts.chartCount();
    // Charts to cut, found first: most models have none, and then nothing is rebuilt. Each chart
    // is measured alone: runs of charts of about equal faces on up to options.threads threads.
    std::vector<char> sparse(chartCount, 0);
    const ChartRuns runs = chartRuns(charts, options.threads);
    const int workers = runs.workers;
    const size_t bands = runs.count();
    const std::vector<size_t> &from = runs.from;
    runBands(bands, workers, [&](size_t band) {
        std::vector<uint32_t> entries;
        for (size_t c = from[band]; c < from[band + 1]; ++c) {
            const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            if (charts.isDegenerate(c) || end - first < 2)
                continue;
            entries.resize(end - first);
            for (uint32_t i = first; i < end; ++i)
                entries[i - first] = i;
            sparse[c] = boxOf(charts, entries).fill() < double(options.minFill);
        }
    });
    if (std::find(sparse.begin(), sparse.end(), 1) == sparse.end())
        return 0;

    // The pieces of a cut chart fill the chart's own range of chartFaces, so every face keeps
    // its place but for the reordering inside cut charts: the faces and UVs are rewritten in
    // place there only, the per-chart arrays anew, and faceChart where the charts' numbers moved.
    // Entry (position in chartFaces) of each face of the chart being cut, and the piece each entry
    // of it is in (a label per entry; UINT32_MAX: never cut).
    std::vector<uint32_t> entryOf(charts.faceCount());
    std::vector<uint32_t> label(charts.chartFaces.size(), UINT32_MAX);
    uint32_t nextLabel = 0;

    AtlasCharts rebuilt;                         // the per-chart arrays
    std::vector<uint32_t> newFirst(chartCount);  // per old chart: its first new chart
    std::vector<uint32_t> oldFaces;              // the chart being cut: its faces and UVs as they were
    std::vector<glm::vec2> oldUv;
    // A piece (entries in chart order) of chart c, being cut, becomes a chart, moved to the
    // origin, written at `at` onward (faceChart, which the cuts read, at the end).
    auto emit = [&](size_t c, const std::vector<uint32_t> &piece, const Box &box, size_t &at) {
        rebuilt.chartAxis.push_back(charts.chartAxis[c]);
        rebuilt.chartFirstFace.push_back(uint32_t(at));
        const glm::vec2 lo = box.lo;
        rebuilt.chartSize.push_back(box.hi - box.lo);
        const size_t first = charts.chartFirstFace[c];
        for (uint32_t i : piece) {
            charts.chartFaces[at] = oldFaces[i - first];
            for (int k = 0; k < 3; ++k)
                charts.wedgeUv[3 * at + size_t(k)] = oldUv[3 * (i - first) + size_t(k)] - lo;
            ++at;
        }
    };

    // The edge-connected parts of `side` (entries labelled `side`'s label, all of chart c), each
    // in chart order.
    auto parts = [&](size_t c, const std::vector<uint32_t> &side, std::vector<std::vector<uint32_t>> &out) {
        const uint32_t from = nextLabel;
        const uint32_t sideLabel = label[side[0]];
        std::vector<uint32_t> queue;
        for (uint32_t seed : side) {
            if (label[seed] != sideLabel)
                continue;  // already in a part
            const uint32_t part = nextLabel++;
            label[seed] = part;
            queue.assign(1, seed);
            for (size_t q = 0; q < queue.size(); ++q) {
                const uint32_t f = charts.chartFaces[queue[q]];
                for (int k = 0; k < 3; ++k) {
                    const uint32_t h = opposite[3 * size_t(f) + size_t(k)];
                    if (h == kNoOpposite || charts.faceChart[h / 3] != c)
                        continue;
                    const uint32_t e = entryOf[h / 3];
                    if (label[e] == sideLabel)
                        label[e] = part, queue.push_back(e);
                }
            }
        }
        const size_t first = out.size();
        out.resize(first + (nextLabel - from));
        for (uint32_t i : side)
            out[first + (label[i] - from)].push_back(i);
    };

    size_t cut = 0;
    std::vector<std::vector<uint32_t>> stack;
    std::vector<std::pair<std::vector<uint32_t>, Box>> done;  // pieces in chart order, with their boxes
    for (size_t c = 0; c < chartCount; ++c) {
        const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
        newFirst[c] = uint32_t(rebuilt.chartAxis.size());
        if (!sparse[c]) {  // kept whole, as it is
            rebuilt.chartAxis.push_back(charts.chartAxis[c]);
            rebuilt.chartFirstFace.push_back(first);
            rebuilt.chartSize.push_back(charts.chartSize[c]);
            continue;
        }
        std::vector<uint32_t> all(end - first);
        for (uint32_t i = first; i < end; ++i) {
            all[i - first] = i;
            entryOf[charts.chartFaces[i]] = i;
        }
        ++cut;
        for (uint32_t i : all)
            label[i] = nextLabel;
        ++nextLabel;
        stack.clear();
        stack.push_back(std::move(all));
        done.clear();
        while (!stack.empty()) {
            std::vector<uint32_t> piece = std::move(stack.back());
            stack.pop_back();
            const Box box = boxOf(charts, piece);
            if (piece.size() < 2 || box.fill() >= double(options.minFill)) {
                done.emplace_back(std::move(piece), box);
                continue;
            }
            // Across the longer side, at its middle; by the centroids' median if one side is empty.
            const int axis = box.hi.x - box.lo.x >= box.hi.y - box.lo.y ? 0 : 1;
            std::vector<float> centre(piece.size());
            for (size_t j = 0; j < piece.size(); ++j) {
                const glm::vec2 *uv = &charts.wedgeUv[3 * size_t(piece[j])];
                centre[j] = (uv[0][axis] + uv[1][axis] + uv[2][axis]) / 3.0f;
            }
            float mid = 0.5f * (box.lo[axis] + box.hi[axis]);
            const size_t below = size_t(std::count_if(centre.begin(), centre.end(), [&](float v) { return v < mid; }));
            if (below == 0 || below == piece.size()) {
                std::vector<float> sorted = centre;
                std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
                mid = sorted[sorted.size() / 2];
                if (std::count_if(centre.begin(), centre.end(), [&](float v) { return v < mid; }) == 0) {
                    done.emplace_back(std::move(piece), box);  // every centroid the same: cannot be cut
                    continue;
                }
            }
            std::vector<uint32_t> sides[2];
            const uint32_t lowLabel = nextLabel++, highLabel = nextLabel++;
            for (size_t j = 0; j < piece.size(); ++j) {
                const bool low = centre[j] < mid;
                label[piece[j]] = low ? lowLabel : highLabel;
                sides[low ? 0 : 1].push_back(piece[j]);
            }
            std::vector<std::vector<uint32_t>> split;
            for (const std::vector<uint32_t> &side : sides)
                parts(c, side, split);
            for (std::vector<uint32_t> &p : split)
                stack.push_back(std::move(p));
        }
        // Each piece keeps the chart's order (sides and parts keep it); pieces by their first faces.
        std::sort(done.begin(), done.end(), [](const auto &a, const auto &b) { return a.first[0] < b.first[0]; });
        oldFaces.assign(charts.chartFaces.begin() + first, charts.chartFaces.begin() + end);
        oldUv.assign(charts.wedgeUv.begin() + 3 * std::ptrdiff_t(first),
                     charts.wedgeUv.begin() + 3 * std::ptrdiff_t(end));
        size_t at = first;
        for (const auto &[piece, box] : done)
            emit(c, piece, box, at);
    }
    rebuilt.chartFirstFace.push_back(uint32_t(charts.chartFaces.size()));

    // The faces' new charts where their numbers moved (pieces, and charts after the first cut
    // one), side by side: each run's charts' faces alone.
    newFirst.push_back(uint32_t(rebuilt.chartAxis.size()));
    runBands(bands, workers, [&](size_t band) {
        for (size_t c = from[band]; c < from[band + 1]; ++c) {
            if (!sparse[c] && newFirst[c] == c)
                continue;
            for (uint32_t n = newFirst[c]; n < newFirst[c + 1]; ++n)
                for (uint32_t i = rebuilt.chartFirstFace[n]; i < rebuilt.chartFirstFace[n + 1]; ++i)
                    charts.faceChart[charts.chartFaces[i]] = n;
        }
    });
    charts.chartFirstFace.swap(rebuilt.chartFirstFace);
    charts.chartAxis.swap(rebuilt.chartAxis);
    charts.chartSize.swap(rebuilt.chartSize);
    charts.splitCharts += cut;
    return cut;
}

}  // namespace voxelfair
