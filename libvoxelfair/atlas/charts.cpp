#include "atlas/charts.h"

#include "atlas/chart_runs.h"
#include "atlas/chart_merge.h"
#include "atlas/chart_split.h"
#include "atlas/chart_overlap.h"
#include "atlas/edge_adjacency.h"
#include "atlas/seed_plane.h"
#include "atlas/texel_raster.h"
#include "base/parallel_bands.h"
#include "base/radix_sort.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair {
namespace {

// An angle without trigonometry: the direction's position around the unit diamond |x| + |y| = 1,
// scaled to a full turn of 2 pi; monotonic in the true angle, all the fold check needs.
constexpr double kDiamondTurn = 6.283185307179586;
double diamondAngle(glm::dvec2 d) {
    const double t = d.y / (std::abs(d.x) + std::abs(d.y));  // -1..1
    const double quarter = kDiamondTurn / 4;
    return d.x >= 0 ? (d.y >= 0 ? t : 4 + t) * quarter : (2 - t) * quarter;
}

bool finite(const glm::vec3 &v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

double AtlasCharts::projectedArea() const {
    double area = 0;
    for (size_t c = 0; c < chartCount(); ++c)
        if (!isDegenerate(c))
            for (uint32_t i = chartFirstFace[c]; i < chartFirstFace[c + 1]; ++i) {
                const glm::vec2 *uv = &wedgeUv[3 * size_t(i)];
                area += 0.5 * std::abs(doubleArea(uv[0], uv[1], uv[2]));
            }
    return area;
}

AtlasCharts computeCharts(const AtlasMesh &mesh, const ChartOptions &options) {
    AtlasCharts out;
    validateAtlasMesh(mesh);
    if (mesh.faceCount == 0)
        return out;
    const size_t faceCount = mesh.faceCount;
    const float cone = options.minSeedCosine >= 0.05f ? std::min(options.minSeedCosine, 1.0f) : 0.05f;

    // Per face, the unit normal that chooses seeds and cones (the caller's when usable, else the
    // geometric one) and the unit geometric normal; both zero for a degenerate face, which so
    // never passes a cone test (cone >= 0.05). Side by side for the breadth-first search.
    using FaceNormals = ChartFaceNormals;
    // Left uninitialised here and written (zeros included) face by face, on the threads.
    const std::unique_ptr<FaceNormals[]> normals(new FaceNormals[faceCount]);
    std::vector<uint8_t> degenerate(faceCount, 0);
    std::vector<uint32_t> order;
    // Faces [begin, end)'s normals; returns (non-finite faces, ignored normals).
    auto faceNormals = [&](size_t begin, size_t end) {
        std::pair<size_t, size_t> counts{0, 0};
        for (size_t f = begin; f < end; ++f) {
            const uint32_t *t = mesh.triangles + 3 * f;
            const glm::dvec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
            normals[f] = FaceNormals{glm::vec3(0.0f), glm::vec3(0.0f)};
            if (!finite(glm::vec3(p0)) || !finite(glm::vec3(p1)) || !finite(glm::vec3(p2))) {
                degenerate[f] = 1;
                ++counts.first;
                continue;
            }
            const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
            const double longest2 =
                std::max({glm::dot(p1 - p0, p1 - p0), glm::dot(p2 - p0, p2 - p0), glm::dot(p2 - p1, p2 - p1)});
            const double length = glm::length(cross);
            if (!(length > 1e-6 * longest2) || !std::isfinite(length)) {
                degenerate[f] = 1;
                continue;
            }
            FaceNormals &n = normals[f];
            n.geometric = n.cone = glm::vec3(cross / length);
            if (mesh.faceNormals) {
                const glm::vec3 given = mesh.faceNormals[f];
                const float len = glm::length(given);
                if (finite(given) && len > 0 && std::isfinite(len) && glm::dot(given / len, n.geometric) >= cone)
                    n.cone = given / len;
                else
                    ++counts.second;
            }
        }
        return counts;
    };
    // Seed order: largest |component| first, face order among equals. For positive floats the
    // bit pattern orders like the value, so ~bits sorts descending.
    auto seedOrder = [&] {
        std::vector<uint64_t> keyed;  // per face: its key above its index
        keyed.reserve(faceCount);
        for (size_t f = 0; f < faceCount; ++f) {
            if (degenerate[f])
                continue;
            const glm::vec3 &n = normals[f].cone;
            const float priority = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
            uint32_t bits;
            std::memcpy(&bits, &priority, sizeof bits);
            keyed.push_back((uint64_t(~bits) << 32) | f);
        }
        std::vector<uint64_t> scratch;
        radixSortStable(keyed, scratch, [](uint64_t w) { return uint32_t(w >> 32); });
        order.resize(keyed.size());
        for (size_t i = 0; i < keyed.size(); ++i)
            order[i] = uint32_t(keyed[i]);
    };
    // On two threads for larger meshes: the edge adjacency (which does not depend on the normals)
    // beside the normals and the seed order. The second thread takes the last twelfth of the faces'
    // normals first (the adjacency takes longer than the sort), the first one waits for them
    // before it orders the seeds: each face's normal is computed alone, so the same as on one.
    EdgeAdjacency adjacency;
    std::pair<size_t, size_t> headCounts{0, 0}, tailCounts{0, 0};
    if (faceCount >= kLeastParallelFaces && bandThreads(options.threads, 2) == 2) {
        const size_t split = faceCount - faceCount / 12;
        std::atomic<bool> tailDone{false};
        runBands(2, 2, [&](size_t band) {
            if (band == 1) {
                tailCounts = faceNormals(split, faceCount);
                tailDone.store(true, std::memory_order_release);
                adjacency = buildEdgeAdjacency(mesh.triangles, faceCount, mesh.vertexCount);
                return;
            }
            headCounts = faceNormals(0, split);
            while (!tailDone.load(std::memory_order_acquire))  // two bands on two threads: never waits on itself
                std::this_thread::yield();
            seedOrder();
        });
    } else {
        headCounts = faceNormals(0, faceCount);
        seedOrder();
        adjacency = buildEdgeAdjacency(mesh.triangles, faceCount, mesh.vertexCount);
    }
    out.nonFiniteFaces = headCounts.first + tailCounts.first;
    out.ignoredNormals = headCounts.second + tailCounts.second;
    if (adjacency.borderEdges > faceCount) {
        // More border edges than faces: the mesh stores its corners unshared. Match edges by
        // position instead (vertex ids still tell the UV seams apart).
        const std::vector<uint32_t> welded =
            weldByPosition(mesh.positions, mesh.vertexCount, mesh.triangles, faceCount);
        adjacency = buildEdgeAdjacency(welded.data(), faceCount, mesh.vertexCount);
        out.weldedByPosition = true;
    }
    out.nonManifoldEdges = adjacency.nonManifoldEdges;
    out.borderEdges = adjacency.borderEdges;

    constexpr uint32_t kFree = std::numeric_limits<uint32_t>::max();
    out.faceChart.assign(faceCount, kFree);
    out.chartFaces.reserve(faceCount);
    out.wedgeUv.resize(3 * faceCount);

    // Breadth-first growth from `seed`: the queue, in a buffer of its own (written through a
    // pointer, no capacity check per face), is the chart's faces in order, appended at the end.
    // The queue stands where the chart's faces stand in chartFaces, so the buffer holds the same
    // faces there (read by the fold checks beside the growth, which leave chartFaces alone).
    auto scaleOf = [&](uint32_t f) { return mesh.faceTexelScale ? mesh.faceTexelScale[f] : 1.0f; };
    std::vector<uint32_t> growQueue(faceCount);
    auto grow = [&](uint32_t seed) {
        const uint32_t chart = uint32_t(out.chartAxis.size());
        const glm::vec3 axis = normals[seed].cone;
        const float scale = scaleOf(seed);
        out.chartAxis.push_back(axis);
        out.chartFirstFace.push_back(uint32_t(out.chartFaces.size()));
        out.faceChart[seed] = chart;
        uint32_t *queue = growQueue.data() + out.chartFaces.size();
        size_t queued = 0;
        queue[queued++] = seed;
        for (size_t q = 0; q < queued; ++q) {
            const uint32_t f = queue[q];
            for (uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
                const uint32_t o = adjacency.opposite[h];
                if (o == kNoOpposite || out.faceChart[o / 3] != kFree || scaleOf(o / 3) != scale)
                    continue;
                const FaceNormals &n = normals[o / 3];
                if (glm::dot(axis, n.cone) >= cone && glm::dot(axis, n.geometric) >= cone) {
                    out.faceChart[o / 3] = chart;
                    queue[queued++] = o / 3;
                }
            }
        }
        out.chartFaces.insert(out.chartFaces.end(), queue, queue + queued);
        return chart;
    };

    // Orthographic projection of a chart (faces[first] up to faces[end] of `faces`, chartFaces or
    // the growth's buffer) onto its seed plane (its seed's normal: its axis), relative to the
    // seed's first corner (keeps the numbers small), shifted so its box starts at the origin;
    // returns the box's size. Writes the chart's UVs only.
    auto projectFaces = [&](const uint32_t *faces, size_t first, size_t end) {
        glm::vec2 *uv = out.wedgeUv.data() + 3 * first, *uvEnd = out.wedgeUv.data() + 3 * end;
        faces += first;
        const SeedPlane plane = seedPlane(glm::normalize(glm::dvec3(normals[faces[0]].cone)));
        const glm::dvec3 origin = mesh.positions[mesh.triangles[3 * faces[0]]];
        const double scale = scaleOf(faces[0]);
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (glm::vec2 *w = uv; w != uvEnd; ++faces)
            for (int k = 0; k < 3; ++k, ++w) {
                *w = projectOnPlane(plane, origin, mesh.positions[mesh.triangles[3 * *faces + k]], scale);
                lo = glm::min(lo, *w);
                hi = glm::max(hi, *w);
            }
        for (glm::vec2 *w = uv; w != uvEnd; ++w)
            *w -= lo;
        return hi - lo;
    };
    // The last chart's projection.
    auto project = [&](size_t c) {
        out.chartSize.push_back(projectFaces(out.chartFaces.data(), out.chartFirstFace[c], out.chartFaces.size()));
    };

    // Whether chart c's projection (faces[first] up to faces[end], its UVs written) winds over
    // itself (chart_overlap.h). Reads the chart's own faces and UVs only (a face's neighbour is in
    // the chart when stamped with the check's round, not by faceChart, which the growth beside
    // may be writing): checks of grown charts can run side by side, each with its own scratch.
    struct FoldScratch {
        std::vector<ChartBoundaryEdge> boundary;
        std::vector<ChartCorner> corners;
        CornerGroups grouped;
        // Per vertex: the last chart it bounded, and its number in the check (`round`) that last
        // numbered it. A chart checked again after a cut keeps its earlier boundary's stamps.
        struct Stamp {
            uint32_t chart = UINT32_MAX, round = 0, group = 0;
        };
        std::vector<Stamp> boundaryStamp;
        std::vector<uint32_t> faceRound;  // per face: the last check whose chart held it
        uint32_t round = 0;
    };
    auto foldsOver = [&](uint32_t c, const uint32_t *faces, size_t first, size_t end, FoldScratch &s) {
        const uint32_t round = ++s.round;
        if (s.faceRound.empty())
            s.faceRound.assign(faceCount, 0);
        for (size_t i = first; i < end; ++i)
            s.faceRound[faces[i]] = round;
        s.boundary.clear();
        for (size_t i = first; i < end; ++i) {
            const uint32_t f = faces[i];
            for (int k = 0; k < 3; ++k) {
                const uint32_t o = adjacency.opposite[3 * f + k];
                if (o != kNoOpposite && s.faceRound[o / 3] == round)
                    continue;
                const int k1 = (k + 1) % 3;
                s.boundary.push_back({out.wedgeUv[3 * i + k], out.wedgeUv[3 * i + k1], mesh.triangles[3 * f + k],
                                      mesh.triangles[3 * f + k1]});
            }
        }
        if (boundaryCrossesItself(s.boundary))
            return true;
        // Only the boundary's vertices, numbered as met: around an inner vertex the chart's faces
        // close one fan.
        uint32_t groups = 0;
        for (const ChartBoundaryEdge &e : s.boundary)
            for (uint32_t v : {e.va, e.vb}) {
                if (v >= s.boundaryStamp.size())
                    s.boundaryStamp.resize(size_t(v) + 1);
                if (s.boundaryStamp[v].chart != c || s.boundaryStamp[v].round != round)
                    s.boundaryStamp[v] = {c, round, groups++};
            }
        s.corners.clear();
        for (size_t i = first; i < end; ++i) {
            const glm::vec2 *w = &out.wedgeUv[3 * i];
            if (doubleArea(w[0], w[1], w[2]) <= 0)
                continue;  // no sector (degenerate in UV)
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = mesh.triangles[3 * size_t(faces[i]) + k];
                if (v >= s.boundaryStamp.size() || s.boundaryStamp[v].chart != c)
                    continue;
                if (s.boundaryStamp[v].round != round)  // bounded the chart before a cut
                    s.boundaryStamp[v] = {c, round, groups++};
                const double from = diamondAngle(glm::dvec2(w[(k + 1) % 3] - w[k]));
                double to = diamondAngle(glm::dvec2(w[(k + 2) % 3] - w[k]));
                to += to < from ? kDiamondTurn : 0;
                s.corners.push_back({s.boundaryStamp[v].group, from, to - from});
            }
        }
        return cornersOverlap(s.corners, groups, s.grouped);
    };
    FoldScratch scratch;
    // The last chart, cut back to the half of its faces nearest its seed (a prefix of the
    // breadth-first order, so still connected) while it winds over itself; true if it was.
    auto cutWhileFolded = [&](uint32_t c) {
        bool cut = false;
        while (foldsOver(c, out.chartFaces.data(), out.chartFirstFace[c], out.chartFaces.size(), scratch)) {
            const size_t first = out.chartFirstFace[c];
            const size_t keep = first + std::max<size_t>(1, (out.chartFaces.size() - first) / 2);
            for (size_t i = keep; i < out.chartFaces.size(); ++i)
                out.faceChart[out.chartFaces[i]] = kFree;
            out.chartFaces.resize(keep);
            out.chartSize.pop_back();
            project(c);
            ++out.foldedCharts;
            cut = true;
        }
        return cut;
    };

    // Charts in seed order, each checked for folds as it is grown; the faces a folded chart lets
    // go are charted in a further pass. The first pass of a larger mesh is grown whole while the
    // other threads project and check each chart as soon as it is grown (the main thread joins
    // them when the growth is done): the checks read only the growth's buffer, the normals and
    // each its own chart's UVs, so without a fold that is the same as checking each at once. At
    // the first chart that folds, the charts grown after it are dropped (their faces freed) and the
    // pass goes on from its seed as before.
    const int foldWorkers = faceCount >= kLeastParallelFaces ? bandThreads(options.threads, 2) : 1;
    bool speculate = foldWorkers > 1;
    for (bool released = true; released;) {
        released = false;
        size_t next = 0;  // the position in `order` to go on from
        if (speculate) {
            speculate = false;
            const uint32_t firstChart = uint32_t(out.chartAxis.size());
            const size_t firstFace = out.chartFaces.size();
            std::vector<size_t> seedAt;  // per chart grown here: its seed's position in `order`
            // Per chart grown here (at most one a face): its end in the growth's buffer, its size
            // and whether it folds, written by the one thread that grew or checked it (left
            // uninitialised: only the grown charts' are written and read).
            const size_t most = faceCount - firstFace;
            const std::unique_ptr<uint32_t[]> ends(new uint32_t[most]);
            const std::unique_ptr<glm::vec2[]> sizes(new glm::vec2[most]);
            const std::unique_ptr<uint8_t[]> folds(new uint8_t[most]);
            // A thread ahead of the growth sleeps (a busy wait would take the core from the growth
            // on a loaded machine); the growth wakes it when it publishes a chart or ends. Both
            // sides' flags are sequentially consistent: a waiter that counted itself in sees the
            // chart, or the growth sees the waiter.
            std::atomic<size_t> published{0}, taken{0}, waiters{0};  // grown, handed out, asleep
            std::atomic<bool> growing{true};
            std::mutex wakeLock;
            std::condition_variable wake;
            auto publish = [&](size_t grownSoFar) {
                published.store(grownSoFar);
                if (waiters.load() > 0) {
                    const std::lock_guard<std::mutex> lock(wakeLock);
                    wake.notify_all();
                }
            };
            auto checkGrown = [&](FoldScratch &s) {
                for (size_t k = taken++;; k = taken++) {
                    if (k >= published.load() && growing.load()) {
                        std::unique_lock<std::mutex> lock(wakeLock);
                        ++waiters;
                        wake.wait(lock, [&] { return k < published.load() || !growing.load(); });
                        --waiters;
                    }
                    if (k >= published.load())
                        return;  // the growth is done and grew no chart k
                    const size_t first = k > 0 ? ends[k - 1] : firstFace;
                    sizes[k] = projectFaces(growQueue.data(), first, ends[k]);
                    folds[k] = foldsOver(firstChart + uint32_t(k), growQueue.data(), first, ends[k], s);
                }
            };
            std::vector<FoldScratch> scratches(static_cast<size_t>(foldWorkers));
            std::vector<std::thread> checkers;
            checkers.reserve(scratches.size() - 1);
            for (size_t w = 1; w < scratches.size(); ++w)
                checkers.emplace_back(checkGrown, std::ref(scratches[w]));
            for (size_t k = 0; k < order.size(); ++k) {
                if (out.faceChart[order[k]] != kFree)
                    continue;
                grow(order[k]);
                ends[seedAt.size()] = uint32_t(out.chartFaces.size());
                seedAt.push_back(k);
                publish(seedAt.size());
            }
            growing.store(false);
            {
                const std::lock_guard<std::mutex> lock(wakeLock);
                wake.notify_all();
            }
            checkGrown(scratches[0]);
            for (std::thread &t : checkers)
                t.join();
            const size_t grown = seedAt.size();
            auto endOf = [&](size_t c) { return ends[c - firstChart]; };
            out.chartSize.insert(out.chartSize.end(), sizes.get(), sizes.get() + grown);
            const size_t folded = size_t(std::find(folds.get(), folds.get() + grown, 1) - folds.get());
            if (folded == grown)
                break;  // no chart folds: the pass is done, and nothing was let go
            const uint32_t c = firstChart + uint32_t(folded);
            for (size_t i = endOf(c); i < out.chartFaces.size(); ++i)
                out.faceChart[out.chartFaces[i]] = kFree;
            out.chartFaces.resize(endOf(c));
            out.chartFirstFace.resize(size_t(c) + 1);
            out.chartAxis.resize(size_t(c) + 1);
            out.chartSize.resize(size_t(c) + 1);
            released = cutWhileFolded(c);
            next = seedAt[folded] + 1;
        }
        for (; next < order.size(); ++next) {
            const uint32_t seed = order[next];
            if (out.faceChart[seed] != kFree)
                continue;
            const uint32_t c = grow(seed);
            project(c);
            released = cutWhileFolded(c) || released;
        }
    }

    // Degenerate faces: one chart each, a fixed right triangle of one texel.
    for (size_t f = 0; f < faceCount; ++f) {
        if (!degenerate[f])
            continue;
        ++out.degenerateFaces;
        glm::vec2 *uv = out.wedgeUv.data() + 3 * out.chartFaces.size();
        uv[0] = {0, 0};
        uv[1] = {1, 0};
        uv[2] = {0, 1};
        out.faceChart[f] = uint32_t(out.chartAxis.size());
        out.chartAxis.push_back(glm::vec3(0.0f));
        out.chartSize.push_back({1, 1});
        out.chartFirstFace.push_back(uint32_t(out.chartFaces.size()));
        out.chartFaces.push_back(uint32_t(f));
    }
    out.chartFirstFace.push_back(uint32_t(out.chartFaces.size()));

    // Small charts into their neighbours, within the wider cone (chart_merge.h).
    ChartMergeOptions merge;
    merge.mostFaces = options.mergeFaces;
    merge.minCosine = std::max(0.05f, std::min(options.mergeCosine, cone));
    merge.threads = options.threads;
    out.mergedCharts = mergeSmallCharts(mesh, adjacency.opposite.data(), normals.get(), merge, out);
    // Rings and long diagonals into compact pieces (chart_split.h).
    ChartSplitOptions split;
    split.minFill = options.minChartFill;
    split.threads = options.threads;
    splitSparseCharts(adjacency.opposite.data(), split, out);
    out.faceOpposite = std::move(adjacency.opposite);
    return out;
}

}  // namespace voxelfair
