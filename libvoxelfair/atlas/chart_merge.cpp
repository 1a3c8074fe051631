#include "atlas/chart_merge.h"

#include "atlas/chart_runs.h"
#include "atlas/chart_overlap.h"
#include "atlas/edge_adjacency.h"
#include "atlas/seed_plane.h"
#include "base/parallel_bands.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <thread>
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

// A face's UV box.
Box boxOf(const glm::vec2 *t) {
    Box b;
    b.add(t);
    return b;
}

// A large chart's faces bucketed on a uniform grid over its UV box (about two faces per cell),
// each face in the one cell of its box's lower corner, the cells' faces side by side in one array
// (a counting sort: two reads of the chart's faces, no list per cell). Boxes outside the grid are
// clamped to its border cells (insert and query alike). A query widens its cells downward by the
// most cells any face's box spans: a face whose box meets the query's has its upper corner in a
// cell at or above the query's lower one (cells are monotonic in the coordinate), so its lower
// corner lies at most that span below, and every meeting face is found. Faces moved into the
// chart after the grid was built go into every cell their box meets instead, each cell's such
// faces a list threaded through one array of entries (newest first), found without widening.
constexpr uint32_t kGridFaces = 64;  // charts this large get a grid; smaller ones are scanned
struct FaceGrid {
    glm::vec2 lo{0.0f};
    float perCell = 1;
    int nx = 1, ny = 1;
    int spanX = 0, spanY = 0;     // the most cells a face's box reaches past its lower corner's
    std::vector<uint32_t> start;  // per cell, its first face in `faces`; nx * ny + 1 entries
    std::vector<uint32_t> faces;  // the faces, by cell
    struct Entry {
        uint32_t face, next;
    };
    std::vector<uint32_t> addedFirst;  // per cell, its newest added entry (kNone: empty)
    std::vector<Entry> added;          // faces moved in after the grid was built
    int cellX(float v) const { return std::clamp(int((v - lo.x) * perCell), 0, nx - 1); }
    int cellY(float v) const { return std::clamp(int((v - lo.y) * perCell), 0, ny - 1); }
    // The grid of `n` faces `face[i]` with UVs uv[3 i ..]; `cellOf` is scratch.
    void build(const uint32_t *face, const glm::vec2 *uv, size_t n, std::vector<uint32_t> &cellOf) {
        Box all;
        for (size_t i = 0; i < n; ++i)
            all.add(uv + 3 * i);
        const glm::vec2 extent = glm::max(all.hi - all.lo, glm::vec2(1e-20f));
        const double cell = std::sqrt(double(extent.x) * extent.y * 2.0 / double(n));
        lo = all.lo;
        nx = std::clamp(int(extent.x / cell) + 1, 1, 1024);
        ny = std::clamp(int(extent.y / cell) + 1, 1, 1024);
        perCell = float(std::min(nx / double(extent.x), ny / double(extent.y)));
        start.assign(size_t(nx) * ny + 1, 0);
        cellOf.resize(n);
        for (size_t i = 0; i < n; ++i) {
            const Box b = boxOf(uv + 3 * i);
            const int x = cellX(b.lo.x), y = cellY(b.lo.y);
            spanX = std::max(spanX, cellX(b.hi.x) - x);
            spanY = std::max(spanY, cellY(b.hi.y) - y);
            cellOf[i] = uint32_t(y * nx + x);
            ++start[cellOf[i] + 1];
        }
        for (size_t c = 1; c < start.size(); ++c)
            start[c] += start[c - 1];
        faces.resize(n);
        for (size_t i = 0; i < n; ++i)
            faces[start[cellOf[i]]++] = face[i];
        for (size_t c = start.size() - 1; c > 0; --c)  // each cell's end back to its start
            start[c] = start[c - 1];
        start[0] = 0;
    }
    // Adds face f, of box b, after the grid was built.
    void add(uint32_t f, const Box &b) {
        if (addedFirst.empty())
            addedFirst.assign(size_t(nx) * ny, kNone);
        for (int y = cellY(b.lo.y); y <= cellY(b.hi.y); ++y)
            for (int x = cellX(b.lo.x); x <= cellX(b.hi.x); ++x) {
                uint32_t &head = addedFirst[size_t(y) * nx + x];
                added.push_back({f, head});
                head = uint32_t(added.size() - 1);
            }
    }
    // Appends the faces that may meet box `b` (every one that does; an added face once per cell
    // it is in).
    void query(const Box &b, std::vector<uint32_t> &out) const {
        const int x0 = cellX(b.lo.x), x1 = cellX(b.hi.x), y0 = cellY(b.lo.y), y1 = cellY(b.hi.y);
        for (int y = std::max(0, y0 - spanY); y <= y1; ++y) {
            const size_t row = size_t(y) * nx;
            out.insert(out.end(), faces.begin() + start[row + size_t(std::max(0, x0 - spanX))],
                       faces.begin() + start[row + size_t(x1) + 1]);
        }
        if (!addedFirst.empty())
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    for (uint32_t e = addedFirst[size_t(y) * nx + x]; e != kNone; e = added[e].next)
                        out.push_back(added[e].face);
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
    std::vector<uint32_t> head(chartCount), tail(chartCount), count(chartCount), next(faceCount, kNone);
    // `uv` left uninitialised: the set-up writes every face's.
    const std::unique_ptr<glm::vec2[]> uv(new glm::vec2[3 * faceCount]);
    std::vector<glm::vec2> lo(chartCount);
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
    // A chart's grid is built from its own faces as they stand in `charts` (their UVs there are
    // the ones in `uv`: a chart with a grid was never moved). The faces moved into it are added
    // by the merging thread alone: those moved before its first query at that query, later ones
    // as they move (`synced`).
    std::vector<FaceGrid> grids(chartCount);
    std::vector<std::atomic<uint8_t>> gridState(chartCount);  // 0: not begun, 1: being built, 2: built
    std::vector<uint8_t> synced(chartCount, 0);
    // Builds chart a's grid unless another thread began it; true if this one did.
    auto claimGrid = [&](uint32_t a, std::vector<uint32_t> &cellOf) {
        uint8_t notBegun = 0;
        if (!gridState[a].compare_exchange_strong(notBegun, 1, std::memory_order_acq_rel))
            return false;
        const uint32_t first = charts.chartFirstFace[a], end = charts.chartFirstFace[a + 1];
        grids[a].build(&charts.chartFaces[first], &charts.wedgeUv[3 * size_t(first)], end - first, cellOf);
        gridState[a].store(2, std::memory_order_release);
        return true;
    };
    std::vector<uint32_t> cellScratch;
    auto gridOf = [&](uint32_t a) -> const FaceGrid & {
        if (!claimGrid(a, cellScratch))
            while (gridState[a].load(std::memory_order_acquire) != 2)  // being built beside
                std::this_thread::yield();
        if (!synced[a]) {
            synced[a] = 1;
            for (uint32_t f = next[charts.chartFaces[charts.chartFirstFace[a + 1] - 1]]; f != kNone; f = next[f])
                grids[a].add(f, boxOf(&uv[3 * size_t(f)]));
        }
        return grids[a];
    };
    // On more threads, a second thread builds the grids of the large charts next to a small one
    // while the merges run, in the order the merges first ask for them; a grid the merges want
    // before it came to it they build themselves. A grid finds every face whose box meets the
    // query's whenever it was built, so the merges are the same as with grids built on demand.
    std::atomic<bool> merging{true};
    struct Joined {
        std::thread thread;
        ~Joined() {
            if (thread.joinable())
                thread.join();
        }
    } builder;
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
        builder.thread = std::thread([&, gridded = std::move(gridded)] {
            std::vector<uint32_t> cellOf;
            for (size_t k = 0; k < gridded.size() && merging.load(std::memory_order_relaxed); ++k)
                claimGrid(gridded[k], cellOf);
        });
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
                if (!boxOf(&uv[3 * size_t(f)]).meets(box))
                    continue;
                for (size_t i = 0; i < faces.size() && fits; ++i)
                    fits = !overlap(&uv[3 * size_t(f)], &moved[3 * i]);
            }
            if (!fits)
                continue;
            for (size_t i = 0; i < faces.size(); ++i) {
                std::copy_n(&moved[3 * i], 3, &uv[3 * size_t(faces[i])]);
                chartOf[faces[i]] = a;
                if (synced[a])
                    grids[a].add(faces[i], boxOf(&moved[3 * i]));
            }
            next[tail[a]] = head[b];
            tail[a] = tail[b];
            count[a] += count[b];
            count[b] = 0;
            ++merged;
            break;
        }
    }
    merging.store(false, std::memory_order_relaxed);
    if (builder.thread.joinable())
        builder.thread.join();
    if (merged == 0)
        return 0;

    // The charts again, emptied ones left out, each re-boxed to the origin: numbered and given
    // their first faces in order, then filled side by side, faces and UVs in place (from the
    // lists and `uv`, which hold all the set-up read from them).
    AtlasCharts out;
    const size_t kept = chartCount - merged;
    out.chartAxis.resize(kept);
    out.chartFirstFace.resize(kept + 1);
    out.chartSize.resize(kept);
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
                charts.chartFaces[i++] = f;
                chartOf[f] = uint32_t(n);
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
                    charts.wedgeUv[3 * j + size_t(k)] = uv[3 * size_t(charts.chartFaces[j]) + k] - least;
        }
    });
    charts.chartFirstFace = std::move(out.chartFirstFace);
    charts.chartAxis = std::move(out.chartAxis);
    charts.chartSize = std::move(out.chartSize);
    return merged;
}

}  // namespace voxelfair
