#include "atlas/crowded_faces.h"

#include "atlas/chart_runs.h"
#include "atlas/seed_plane.h"
#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"
#include "base/radix_sort.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair {
namespace {

// sqrt(2) texels, the reach of one texel's diagonal, plus a margin for the rounding of the
// final UVs (about 1e-3 texel in a 16384 texture as floats; the bake paints every texel within
// kUvRounding = 1/256 of a thin face's interior points, texel_raster.h): the bake's own
// threshold is sqrt(2) + 2 kUvRounding, so every face it treats as thin is thin here too.
constexpr double kReach = 1.41421356237309505 + 0.01;

// Faces thinner than this (texels) may lose their UV area to float rounding once packed, and
// packing then gives them a tiny triangle at their first corner (packing.h): their interior
// points move there, out of this search's sight. In a chart with other colours they are
// separated whatever their neighbours.
constexpr double kFloatThin = 0.01;

// One chart's interior points in a uniform grid of cells at least 2 * kReach texels wide, so
// the points within kReach of a query point lie in at most 4 cells. Cells grow with the chart's
// area over its point count, which bounds the grid by the points, not by the chart's size.
class ChartPointGrid {
public:
    struct Point {
        glm::dvec2 p;
        uint32_t owner;
        uint32_t colour;  // the owner's colour, packed (in what would be padding)
    };

    void build(glm::dvec2 size, const std::vector<Point> &points) {
        perCell_ = 1 / std::max(2 * kReach, std::sqrt(std::max(size.x * size.y, 1.0) / double(points.size())));
        width_ = index(size.x) + 2;
        height_ = index(size.y) + 2;
        start_.assign(size_t(width_) * height_ + 1, 0);
        for (const Point &q : points)
            ++start_[cellOf(q.p) + 1];
        for (size_t c = 1; c < start_.size(); ++c)
            start_[c] += start_[c - 1];
        fill_.assign(start_.begin(), start_.end() - 1);
        entries_.resize(points.size());
        for (const Point &q : points)
            entries_[fill_[cellOf(q.p)]++] = q;
    }

    // Calls visit(point) for every point within kReach of p until visit returns true; returns
    // whether it did.
    template <class Visit>
    bool anyNear(glm::dvec2 p, Visit &&visit) const {
        const int x0 = clampX(index(p.x - kReach)), x1 = clampX(index(p.x + kReach));
        const int y0 = clampY(index(p.y - kReach)), y1 = clampY(index(p.y + kReach));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const size_t c = size_t(y) * width_ + size_t(x);
                for (uint32_t e = start_[c]; e < start_[c + 1]; ++e) {
                    const glm::dvec2 d = entries_[e].p - p;
                    if (glm::dot(d, d) < kReach * kReach && visit(entries_[e]))
                        return true;
                }
            }
        return false;
    }

private:
    // Cell column or row of a coordinate; the grid starts one cell below zero. Monotonic in v,
    // which is all the search needs: a point within kReach of p lies in the cells of p +- kReach.
    int index(double v) const {
        const double cells = v * perCell_;
        return (std::abs(cells) < 1e9 ? floorToInt(cells) : int(std::floor(cells))) + 1;  // floorToInt: no libm call
    }
    int clampX(int x) const { return std::clamp(x, 0, width_ - 1); }
    int clampY(int y) const { return std::clamp(y, 0, height_ - 1); }
    size_t cellOf(glm::dvec2 p) const { return size_t(clampY(index(p.y))) * width_ + size_t(clampX(index(p.x))); }

    double perCell_ = 1;  // cells per texel
    int width_ = 0, height_ = 0;
    std::vector<uint32_t> start_, fill_;
    std::vector<Point> entries_;
};

// Face f's UV triangle in texels, projected onto its own plane and boxed at the origin.
void projectAlone(const AtlasMesh &mesh, uint32_t f, glm::vec2 uv[3], glm::vec3 &axis, glm::vec2 &size) {
    const uint32_t *t = mesh.triangles + 3 * size_t(f);
    const glm::dvec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
    const glm::dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    const SeedPlane plane = seedPlane(n);
    const glm::dvec3 d[3] = {glm::dvec3(0.0), p1 - p0, p2 - p0};
    glm::dvec2 q[3], lo(std::numeric_limits<double>::max());
    for (int k = 0; k < 3; ++k) {
        q[k] = {glm::dot(d[k], plane.t1), glm::dot(d[k], plane.t2)};
        lo = glm::min(lo, q[k]);
    }
    glm::dvec2 hi(0.0);
    const double scale = mesh.faceTexelScale ? mesh.faceTexelScale[f] : 1.0;
    lo *= scale;
    for (int k = 0; k < 3; ++k) {
        q[k] *= scale;
        uv[k] = glm::vec2(q[k] - lo);
        hi = glm::max(hi, q[k] - lo);
    }
    axis = glm::vec3(n);
    size = glm::vec2(hi);
}

}  // namespace

CrowdedFaces separateCrowdedFaces(const AtlasMesh &mesh, AtlasCharts &charts, const CrowdedFaceOptions &options) {
    CrowdedFaces out;
    const double d = options.texelsPerUnit;
    if (mesh.faceColours == nullptr || mesh.faceCount == 0 || charts.faceCount() != mesh.faceCount || !(d > 0) ||
        !std::isfinite(d))
        return out;
    const size_t entries = charts.chartFaces.size();
    auto colour = [&](size_t i) { return mesh.faceColours[charts.chartFaces[i]]; };
    auto packed = [](glm::u8vec3 c) { return uint32_t(c.r) | uint32_t(c.g) << 8 | uint32_t(c.b) << 16; };
    auto points = [&](size_t i, glm::dvec2 p[4]) {
        glm::dvec2 q[3];
        for (int k = 0; k < 3; ++k)
            q[k] = glm::dvec2(charts.wedgeUv[3 * i + k]) * d;
        const double r = faceInteriorPoints(q, p);
        if (!(r > 0))
            p[0] = p[1] = p[2] = p[3] = q[0];  // no area in UV: its corner stands for it
        return r;
    };

    // Chart by chart, thinnest first: a thin face leaves its chart when an interior point of a
    // face of another colour still in the chart lies within kReach of one of its own. Charts are
    // searched apart (on up to options.threads threads) and their counts summed in chart order, so the result is the same for any thread count; the sum
    // stops once over the budget, where the chart-by-chart search stopped.
    const double budget = options.maxSeparatedShare * double(mesh.faceCount);
    std::vector<uint8_t> separated(entries, 0);
    const size_t chartCount = charts.chartCount();
    std::vector<uint32_t> thinCount(chartCount, 0), crowdedCount(chartCount, 0);
    struct Thin {
        double inradius;
        uint32_t entry;
    };
    struct Scratch {
        std::vector<Thin> thin, sorted;
        std::vector<ChartPointGrid::Point> chartPoints;
        ChartPointGrid grid;
    };
    // A chart whose own crowded faces pass the budget ends the ordered sum at or before it: its
    // search stops there (the sum reports only that it passed), and the searches of the charts
    // after it, whose counts the sum never reaches, are left off.
    std::atomic<size_t> passedAt{SIZE_MAX};
    auto unneeded = [&](uint32_t c) { return passedAt.load(std::memory_order_relaxed) < c; };
    auto search = [&](uint32_t c, Scratch &s) {
        const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
        bool mixed = false;
        for (uint32_t i = first + 1; i < end && !mixed; ++i)
            mixed = colour(i) != colour(first);
        s.thin.clear();
        s.chartPoints.clear();
        if (mixed)
            s.chartPoints.reserve(4 * size_t(end - first));
        glm::dvec2 p[4] = {};
        for (uint32_t i = first; i < end; ++i) {
            if ((i - first) % 4096 == 4095 && unneeded(c))
                return;
            const double inradius = points(i, p);
            if (inradius < kReach)
                s.thin.push_back({inradius, i});
            if (mixed) {
                const uint32_t own = packed(colour(i));
                for (const glm::dvec2 &q : p)
                    s.chartPoints.push_back({q, i, own});
            }
        }
        thinCount[c] = uint32_t(s.thin.size());
        if (!mixed || s.thin.empty())
            return;
        s.grid.build(glm::dvec2(charts.chartSize[c]) * d, s.chartPoints);
        // Thinnest first, in chart order among equals (they were noted in chart order).
        radixSortStable(s.thin, s.sorted, [](const Thin &t) { return orderedKey(t.inradius); });
        for (const Thin &t : s.thin) {
            const uint32_t i = t.entry;
            const ChartPointGrid::Point *own = &s.chartPoints[4 * size_t(i - first)];
            separated[i] = t.inradius < kFloatThin;
            for (int k = 0; k < 4 && !separated[i]; ++k)
                separated[i] = s.grid.anyNear(own[k].p, [&](const ChartPointGrid::Point &other) {
                    return other.colour != own[k].colour && other.owner != i && !separated[other.owner];
                });
            crowdedCount[c] += separated[i];
            if (double(crowdedCount[c]) > budget) {
                size_t seen = passedAt.load();
                while (c < seen && !passedAt.compare_exchange_weak(seen, c)) {
                }
                return;
            }
            if (unneeded(c))
                return;
        }
    };
    // The threads take the charts in order; once the faces found crowded pass the budget no
    // chart is started, so every chart before the one where the ordered sum passes it was searched.
    const int workers = entries >= kLeastParallelFaces ? bandThreads(options.threads, chartCount) : 1;
    std::vector<Scratch> scratch(static_cast<size_t>(workers));
    std::atomic<size_t> found{0};
    runWorkerBands(chartCount, workers, [&](size_t c, int worker) {
        if (charts.isDegenerate(c) || double(found.load(std::memory_order_relaxed)) > budget)
            return;
        search(uint32_t(c), scratch[size_t(worker)]);
        found += crowdedCount[c];
    });
    for (uint32_t c = 0; c < chartCount; ++c) {
        out.thinFaces += thinCount[c];
        const size_t before = out.crowdedFaces;
        out.crowdedFaces += crowdedCount[c];
        if (crowdedCount[c] > 0 && double(out.crowdedFaces) > budget) {
            // Where the chart-by-chart search stopped: the first count over the budget.
            out.crowdedFaces = budget >= double(before + 1) ? size_t(std::floor(budget)) + 1 : before + 1;
            return out;
        }
    }
    if (out.crowdedFaces == 0)
        return out;
    out.separatedFaces = out.crowdedFaces;

    // Rebuild the charts: the remaining faces of each chart (re-boxed where faces left), then one
    // chart per separated face, then the degenerate faces' charts, which stay last. Each chart's
    // kept faces and box are found on runs of charts side by side, numbered in chart order, then
    // written side by side, each chart and separated face at its place.
    const ChartRuns runs = chartRuns(charts, options.threads);
    struct Kept {
        uint32_t faces = 0, separated = 0;  // faces staying, faces leaving
        glm::vec2 lo{0.0f}, hi{0.0f};       // the staying faces' box
        bool boxed = false;                 // a box was found (the chart stays)
    };
    std::vector<Kept> kept(chartCount);
    runBands(runs.count(), runs.workers, [&](size_t run) {
        for (size_t c = runs.from[run]; c < runs.from[run + 1]; ++c) {
            if (charts.isDegenerate(c))
                continue;
            const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
            Kept &k = kept[c];
            for (uint32_t i = first; i < end; ++i) {
                k.separated += separated[i];
                if (!separated[i])
                    for (int j = 0; j < 3; ++j) {
                        lo = glm::min(lo, charts.wedgeUv[3 * i + j]);
                        hi = glm::max(hi, charts.wedgeUv[3 * i + j]);
                    }
            }
            k.faces = end - first - k.separated;
            k.boxed = !(hi.x < lo.x);
            if (k.separated == 0)
                lo = glm::vec2(0.0f), hi = charts.chartSize[c];
            k.lo = lo;
            k.hi = hi;
        }
    });
    // Per chart: its new number (kNoChart when all its faces left: no box), its first entry, and
    // the new chart of its first separated face.
    constexpr uint32_t kNoChart = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> number(chartCount, kNoChart), at(chartCount, 0), alone(chartCount, 0);
    uint32_t keptCharts = 0, keptEntries = 0, degenerateCharts = 0;
    for (uint32_t c = 0; c < chartCount; ++c) {
        if (charts.isDegenerate(c)) {
            ++degenerateCharts;
        } else if (kept[c].boxed) {
            number[c] = keptCharts++;
            at[c] = keptEntries;
            keptEntries += kept[c].faces;
        }
    }
    uint32_t separatedCount = 0;
    for (uint32_t c = 0; c < chartCount; ++c) {
        alone[c] = keptCharts + separatedCount;
        separatedCount += charts.isDegenerate(c) ? 0 : kept[c].separated;
    }
    const size_t newCharts = size_t(keptCharts) + separatedCount + degenerateCharts;
    const size_t newEntries = size_t(keptEntries) + separatedCount + degenerateCharts;
    AtlasCharts rebuilt;
    rebuilt.chartFirstFace.resize(newCharts + 1);
    rebuilt.chartAxis.resize(newCharts);
    rebuilt.chartSize.resize(newCharts);
    rebuilt.chartFaces.resize(newEntries);
    rebuilt.wedgeUv.resize(3 * newEntries);
    rebuilt.faceChart.assign(charts.faceCount(), 0);
    // Chart n starting at entry e, holding face f with UVs uv (the first of its faces).
    auto place = [&](uint32_t n, uint32_t e, uint32_t f, const glm::vec2 *uv) {
        rebuilt.faceChart[f] = n;
        rebuilt.chartFaces[e] = f;
        std::copy_n(uv, 3, &rebuilt.wedgeUv[3 * size_t(e)]);
    };
    runBands(runs.count(), runs.workers, [&](size_t run) {
        for (size_t c = runs.from[run]; c < runs.from[run + 1]; ++c) {
            if (charts.isDegenerate(c))
                continue;
            const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            const Kept &k = kept[c];
            if (number[c] != kNoChart) {
                rebuilt.chartFirstFace[number[c]] = at[c];
                rebuilt.chartAxis[number[c]] = charts.chartAxis[c];
                rebuilt.chartSize[number[c]] = k.hi - k.lo;
            }
            uint32_t e = at[c], n = alone[c];
            for (uint32_t i = first; i < end; ++i) {
                if (!separated[i]) {
                    if (number[c] == kNoChart)
                        continue;
                    const glm::vec2 uv[3] = {charts.wedgeUv[3 * i] - k.lo, charts.wedgeUv[3 * i + 1] - k.lo,
                                             charts.wedgeUv[3 * i + 2] - k.lo};
                    place(number[c], e++, charts.chartFaces[i], uv);
                    continue;
                }
                glm::vec2 uv[3];
                projectAlone(mesh, charts.chartFaces[i], uv, rebuilt.chartAxis[n], rebuilt.chartSize[n]);
                rebuilt.chartFirstFace[n] = keptEntries + (n - keptCharts);
                place(n, keptEntries + (n - keptCharts), charts.chartFaces[i], uv);
                ++n;
            }
        }
    });
    for (uint32_t c = 0, n = keptCharts + separatedCount; c < chartCount; ++c)
        if (charts.isDegenerate(c)) {
            rebuilt.chartAxis[n] = charts.chartAxis[c];
            rebuilt.chartSize[n] = charts.chartSize[c];
            rebuilt.chartFirstFace[n] = n - keptCharts + keptEntries;
            place(n, n - keptCharts + keptEntries, charts.chartFaces[charts.chartFirstFace[c]],
                  &charts.wedgeUv[3 * size_t(charts.chartFirstFace[c])]);
            ++n;
        }
    rebuilt.chartFirstFace[newCharts] = uint32_t(newEntries);

    charts.swapCharts(rebuilt);
    charts.separatedFaces += out.separatedFaces;
    return out;
}

}  // namespace voxelfair
