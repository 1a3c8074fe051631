#include "atlas/chart_merge.h"

#include "atlas/chart_runs.h"
#include "atlas/chart_overlap.h"
#include "atlas/edge_adjacency.h"
#include "atlas/seed_plane.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// Whether an edge line of counter-clockwise triangle `t` has all of `u` on its closed outer side.
bool separates(const glm::vec2 *t, const glm::vec2 *u) {
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a(t[k]), b(t[(k + 1) % 3]);
        if (orientUv(a, b, glm::dvec2(u[0])) <= 0 && orientUv(a, b, glm::dvec2(u[1])) <= 0 &&
            orientUv(a, b, glm::dvec2(u[2])) <= 0)
            return true;
    }
    return false;
}

// Whether two counter-clockwise triangles' interiors overlap.
bool overlap(const glm::vec2 *t, const glm::vec2 *u) { return !separates(t, u) && !separates(u, t); }

struct Box {
    glm::vec2 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    void add(const glm::vec2 *t) {
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, t[k]);
            hi = glm::max(hi, t[k]);
        }
    }
    bool meets(const Box &o) const { return lo.x < o.hi.x && o.lo.x < hi.x && lo.y < o.hi.y && o.lo.y < hi.y; }
};

// A large chart's faces bucketed on a uniform grid over its UV box (about two faces per cell),
// so a merge looks only at the faces near the small chart. Boxes outside the grid are clamped
// to its border cells on both sides (insert and query), which keeps every meeting pair found.
// Each cell is a list threaded through one array of entries (newest first): one allocation per
// grid, not one per cell (a vector per cell was an eighth of the charts' time on large meshes).
constexpr uint32_t kGridFaces = 64;  // charts this large get a grid; smaller ones are scanned
struct FaceGrid {
    struct Entry {
        uint32_t face, next;
    };
    glm::vec2 lo{0.0f};
    float perCell = 1;
    int nx = 1, ny = 1;
    std::vector<uint32_t> first;  // per cell, its newest entry (kNone: empty)
    std::vector<Entry> entries;
    bool built() const { return !first.empty(); }
    void cellRange(const Box &b, int &x0, int &y0, int &x1, int &y1) const {
        auto cell = [&](float v, float o, int n) { return std::clamp(int((v - o) * perCell), 0, n - 1); };
        x0 = cell(b.lo.x, lo.x, nx), x1 = cell(b.hi.x, lo.x, nx);
        y0 = cell(b.lo.y, lo.y, ny), y1 = cell(b.hi.y, lo.y, ny);
    }
    void insert(uint32_t f, const Box &b) {
        int x0, y0, x1, y1;
        cellRange(b, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                uint32_t &head = first[size_t(y) * nx + x];
                entries.push_back({f, head});
                head = uint32_t(entries.size() - 1);
            }
    }
    // Appends the faces of the cells that box `b` meets (a face once per cell it is in).
    void query(const Box &b, std::vector<uint32_t> &out) const {
        int x0, y0, x1, y1;
        cellRange(b, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (uint32_t e = first[size_t(y) * nx + x]; e != kNone; e = entries[e].next)
                    out.push_back(entries[e].face);
    }
};

}  // namespace

size_t mergeSmallCharts(const AtlasMesh &mesh, const uint32_t *opposite, const ChartFaceNormals *normals,
                        const ChartMergeOptions &options, AtlasCharts &charts) {
    const size_t chartCount = charts.chartCount();
    if (options.mostFaces == 0 || chartCount < 2)
        return 0;
    const size_t faceCount = charts.faceCount();
    auto scaleOf = [&](uint32_t f) { return mesh.faceTexelScale ? mesh.faceTexelScale[f] : 1.0f; };

    // Runs of charts of about equal faces, a few per thread, for the steps that take each chart
    // (or face) alone: the set-up and the rebuilt charts, the same for any thread count.
    const ChartRuns runs = chartRuns(charts, options.threads);
    const int workers = runs.workers;
    const size_t bands = runs.count();
    const std::vector<size_t> &from = runs.from;

    // Each chart's faces as a list (head, tail, next), UVs per face (3f + k) in its chart's frame:
    // the chart's seed plane and origin, minus the shift `lo` that put its box at the origin.
    // Each face's UV box is kept with its UVs (a moved face's updated when it moves).
    std::vector<uint32_t> head(chartCount), tail(chartCount), count(chartCount), next(faceCount, kNone);
    std::vector<glm::vec2> uv(3 * faceCount), lo(chartCount);
    std::vector<Box> boxes(faceCount);
    std::vector<uint32_t> &chartOf = charts.faceChart;
    runBands(bands, workers, [&](size_t band) {
        for (size_t c = from[band]; c < from[band + 1]; ++c) {
            const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            head[c] = charts.chartFaces[first];
            tail[c] = charts.chartFaces[end - 1];
            count[c] = end - first;
            for (uint32_t i = first; i < end; ++i) {
                const uint32_t f = charts.chartFaces[i];
                if (i + 1 < end)
                    next[f] = charts.chartFaces[i + 1];
                std::copy_n(&charts.wedgeUv[3 * size_t(i)], 3, &uv[3 * size_t(f)]);
                boxes[f].add(&uv[3 * size_t(f)]);
            }
            lo[c] = -charts.wedgeUv[3 * size_t(first)];  // the seed's first corner projects to (0, 0)
        }
    });

    // Small charts, smallest first (seed order among equals).
    std::vector<uint32_t> small;
    for (size_t c = 0; c < chartCount; ++c)
        if (!charts.isDegenerate(c) && count[c] <= options.mostFaces)
            small.push_back(uint32_t(c));
    std::stable_sort(small.begin(), small.end(), [&](uint32_t a, uint32_t b) { return count[a] < count[b]; });

    struct Candidate {
        uint32_t chart;
        float cosine;
    };
    std::vector<FaceGrid> grids(chartCount);  // built when a large chart is first a candidate
    auto faceBox = [&](uint32_t f) -> const Box & { return boxes[f]; };
    auto gridOf = [&](uint32_t a) -> FaceGrid & {
        FaceGrid &g = grids[a];
        if (g.built())
            return g;
        Box all;
        for (uint32_t f = head[a]; f != kNone; f = next[f])
            all.add(&uv[3 * size_t(f)]);
        const glm::vec2 extent = glm::max(all.hi - all.lo, glm::vec2(1e-20f));
        const double cell = std::sqrt(double(extent.x) * extent.y * 2.0 / count[a]);
        g.lo = all.lo;
        g.nx = std::clamp(int(extent.x / cell) + 1, 1, 1024);
        g.ny = std::clamp(int(extent.y / cell) + 1, 1, 1024);
        g.perCell = float(std::min(g.nx / double(extent.x), g.ny / double(extent.y)));
        g.first.assign(size_t(g.nx) * g.ny, kNone);
        g.entries.reserve(2 * size_t(count[a]));
        for (uint32_t f = head[a]; f != kNone; f = next[f])
            g.insert(f, faceBox(f));
        return g;
    };
    // On more threads, the grids of the large charts next to a small one are built beforehand,
    // side by side (each reads its own chart only). A grid finds every face whose box meets the
    // query's whenever it was built, so the merges are the same as with grids built on demand.
    if (workers > 1) {
        std::vector<uint8_t> wanted(chartCount, 0);
        std::vector<uint32_t> gridded;
        for (const uint32_t b : small)
            for (uint32_t f = head[b]; f != kNone; f = next[f])
                for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
                    const uint32_t o = opposite[h];
                    const uint32_t a = o == kNoOpposite ? b : chartOf[o / 3];
                    if (a != b && !wanted[a] && count[a] >= kGridFaces && !charts.isDegenerate(a)) {
                        wanted[a] = 1;
                        gridded.push_back(a);
                    }
                }
        runBands(gridded.size(), workers, [&](size_t k) { gridOf(gridded[k]); });
    }
    std::vector<uint32_t> near;
    std::vector<Candidate> candidates;
    std::vector<uint32_t> faces;
    std::vector<glm::vec2> moved;
    size_t merged = 0;
    for (const uint32_t b : small) {
        if (count[b] == 0 || count[b] > options.mostFaces)
            continue;
        faces.clear();
        for (uint32_t f = head[b]; f != kNone; f = next[f])
            faces.push_back(f);
        const float scale = scaleOf(faces[0]);
        candidates.clear();
        for (const uint32_t f : faces)
            for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
                const uint32_t o = opposite[h];
                if (o == kNoOpposite)
                    continue;
                const uint32_t a = chartOf[o / 3];
                if (a == b || charts.isDegenerate(a) || scaleOf(o / 3) != scale ||
                    std::any_of(candidates.begin(), candidates.end(), [&](const Candidate &k) { return k.chart == a; }))
                    continue;
                float least = 1;
                for (const uint32_t g : faces)
                    least = std::min({least, glm::dot(charts.chartAxis[a], normals[g].cone),
                                      glm::dot(charts.chartAxis[a], normals[g].geometric)});
                candidates.push_back({a, least});
            }
        std::sort(candidates.begin(), candidates.end(), [&](const Candidate &x, const Candidate &y) {
            return x.cosine != y.cosine ? x.cosine > y.cosine : count[x.chart] > count[y.chart];
        });
        for (const Candidate &k : candidates) {
            if (k.cosine < options.minCosine)
                break;
            const uint32_t a = k.chart;
            // b's faces on a's plane, as a's own projection would place them.
            const SeedPlane plane = seedPlane(glm::normalize(glm::dvec3(charts.chartAxis[a])));
            const glm::dvec3 origin = mesh.positions[mesh.triangles[3 * size_t(head[a])]];
            moved.resize(3 * faces.size());
            Box box;
            bool fits = true;
            for (size_t i = 0; i < faces.size() && fits; ++i) {
                glm::vec2 *t = &moved[3 * i];
                for (int c = 0; c < 3; ++c)
                    t[c] =
                        projectOnPlane(plane, origin, mesh.positions[mesh.triangles[3 * size_t(faces[i]) + c]], scale) -
                        lo[a];
                fits = orientUv(glm::dvec2(t[0]), glm::dvec2(t[1]), glm::dvec2(t[2])) > 0;
                box.add(t);
                for (size_t j = 0; j < i && fits; ++j)
                    fits = !overlap(t, &moved[3 * j]);
            }
            // a's faces whose boxes meet b's: from the grid, or all of a's when small.
            near.clear();
            if (count[a] >= kGridFaces) {
                gridOf(a).query(box, near);
            } else {
                for (uint32_t f = head[a]; f != kNone; f = next[f])
                    near.push_back(f);
            }
            for (size_t n = 0; n < near.size() && fits; ++n) {
                const uint32_t f = near[n];
                if (!faceBox(f).meets(box))
                    continue;
                for (size_t i = 0; i < faces.size() && fits; ++i)
                    fits = !overlap(&uv[3 * size_t(f)], &moved[3 * i]);
            }
            if (!fits)
                continue;
            for (size_t i = 0; i < faces.size(); ++i) {
                std::copy_n(&moved[3 * i], 3, &uv[3 * size_t(faces[i])]);
                boxes[faces[i]] = Box{};
                boxes[faces[i]].add(&moved[3 * i]);
                chartOf[faces[i]] = a;
                if (grids[a].built())
                    grids[a].insert(faces[i], faceBox(faces[i]));
            }
            next[tail[a]] = head[b];
            tail[a] = tail[b];
            count[a] += count[b];
            count[b] = 0;
            ++merged;
            break;
        }
    }
    if (merged == 0)
        return 0;

    // The charts again, emptied ones left out, each re-boxed to the origin: numbered and given
    // their first faces in order, then filled side by side.
    AtlasCharts out;
    const size_t kept = chartCount - merged;
    out.chartAxis.resize(kept);
    out.chartFirstFace.resize(kept + 1);
    out.chartSize.resize(kept);
    out.chartFaces.resize(faceCount);
    out.wedgeUv.resize(3 * faceCount);
    std::vector<uint32_t> renumber(chartCount, kNone);
    for (size_t c = 0, n = 0, at = 0; c < chartCount; ++c) {
        if (count[c] == 0)
            continue;
        renumber[c] = uint32_t(n);
        out.chartFirstFace[n++] = uint32_t(at);
        at += count[c];
    }
    out.chartFirstFace[kept] = uint32_t(faceCount);
    runBands(bands, workers, [&](size_t band) {
        for (size_t c = from[band]; c < from[band + 1]; ++c) {
            if (count[c] == 0)
                continue;
            const size_t n = renumber[c], first = out.chartFirstFace[n];
            out.chartAxis[n] = charts.chartAxis[c];
            glm::vec2 least(std::numeric_limits<float>::max()), most(-std::numeric_limits<float>::max());
            size_t i = first;
            for (uint32_t f = head[c]; f != kNone; f = next[f]) {
                out.chartFaces[i++] = f;
                for (int k = 0; k < 3; ++k) {
                    least = glm::min(least, uv[3 * size_t(f) + k]);
                    most = glm::max(most, uv[3 * size_t(f) + k]);
                }
            }
            if (charts.isDegenerate(c))  // fixed texel UVs: left as they are
                least = glm::vec2(0.0f), most = charts.chartSize[c];
            out.chartSize[n] = most - least;
            for (size_t j = first; j < i; ++j)
                for (int k = 0; k < 3; ++k)
                    out.wedgeUv[3 * j + size_t(k)] = uv[3 * size_t(out.chartFaces[j]) + k] - least;
        }
    });
    for (uint32_t &c : chartOf)
        c = renumber[c];
    charts.chartFirstFace = std::move(out.chartFirstFace);
    charts.chartFaces = std::move(out.chartFaces);
    charts.chartAxis = std::move(out.chartAxis);
    charts.chartSize = std::move(out.chartSize);
    charts.wedgeUv = std::move(out.wedgeUv);
    return merged;
}

}  // namespace voxelfair
