// Section 4.5 texture atlas: charts, packing, bake and the measures, on families of meshes.
#include "atlas/atlas_measures.h"
#include "atlas_checks.h"
#include "shapes/atlas_test_meshes.h"
#include "atlas/chart_masks.h"
#include "atlas/chart_overlap.h"
#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "atlas/texture_atlas.h"
#include "base/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

TestMesh singleTriangle() {
    TestMesh m;
    m.name = "single triangle";
    m.positions = {{0, 0, 0}, {3, 0, 0}, {0, 2, 1}};
    m.triangles = {0, 1, 2};
    m.faceColours = {{10, 20, 30}};
    computeVertexColours(m);
    return m;
}

// Two voxels touching along one edge: that edge is shared by four triangles.
TestMesh edgeTouchingVoxels() {
    TestMesh m = voxelSurface("two voxels sharing an edge", 2, 2, 1,
                              [](int x, int y, int) { return (x == 0 && y == 0) || (x == 1 && y == 1); });
    return m;
}

// A box plus faces without area: a repeated vertex, three collinear points, a coincident pair.
TestMesh boxWithZeroAreaFaces() {
    TestMesh m = voxelBox(3, 2, 2);
    m.name = "box with zero-area faces";
    const uint32_t mid = uint32_t(m.positions.size());
    m.positions.push_back((m.positions[0] + m.positions[1]) * 0.5f);
    const uint32_t twin = uint32_t(m.positions.size());
    m.positions.push_back(m.positions[2]);
    m.triangles.insert(m.triangles.end(), {0, 0, 1, 0, mid, 1, 2, twin, 3});
    for (int i = 0; i < 3; ++i)
        m.faceColours.push_back({uint8_t(50 * i), 200, 7});
    computeVertexColours(m);
    return m;
}

// A ramp winding 1.5 turns around the z axis (radii 3..5, rising 0.5 per radian): every face is
// within a few degrees of +Z, yet the surface lies over itself.
TestMesh helicalRamp() {
    TestMesh m;
    m.name = "helical ramp";
    const int turnsSteps = 120, radialSteps = 4;
    for (int i = 0; i <= turnsSteps; ++i)
        for (int j = 0; j <= radialSteps; ++j) {
            const float t = 3.0f * 3.14159265f * float(i) / turnsSteps, r = 3.0f + 2.0f * float(j) / radialSteps;
            m.positions.push_back({r * std::cos(t), r * std::sin(t), 0.5f * t});
        }
    for (int i = 0; i < turnsSteps; ++i)
        for (int j = 0; j < radialSteps; ++j) {
            const uint32_t a = uint32_t(i * (radialSteps + 1) + j), b = a + uint32_t(radialSteps + 1);
            // Counter-clockwise seen from above (+Z).
            m.triangles.insert(m.triangles.end(), {a, a + 1, b + 1, a, b + 1, b});
            m.faceColours.push_back(voxelColour(i, j, 0));
            m.faceColours.push_back(voxelColour(i, j, 0));
        }
    computeVertexColours(m);
    return m;
}

std::vector<TestMesh> families() {
    std::vector<TestMesh> out;
    out.push_back(voxelSphere(4));
    out.push_back(smoothed(voxelSphere(6)));
    out.push_back(smoothed(voxelSphere(12)));
    out.push_back(voxelBox(5, 3, 2));
    out.push_back(smoothed(voxelBox(6, 6, 6), 5));
    out.push_back(smoothed(voxelTorus(8, 3)));
    out.push_back(smoothed(voxelBlob(7, 1)));
    out.push_back(smoothed(voxelBlob(9, 2), 3));
    out.push_back(edgeTouchingVoxels());
    out.push_back(boxWithZeroAreaFaces());
    out.push_back(singleTriangle());
    out.push_back(helicalRamp());
    return out;
}

glm::dvec3 geometricNormal(const TestMesh &m, size_t f) {
    const glm::dvec3 a = m.positions[m.triangles[3 * f]], b = m.positions[m.triangles[3 * f + 1]],
                     c = m.positions[m.triangles[3 * f + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

// The faces of chart c that a flood over the chart's own edges reaches from its first face (all of
// them when the chart is edge-connected).
size_t facesReached(const AtlasCharts &charts, const EdgeAdjacency &adjacency, size_t c) {
    const uint32_t seed = charts.chartFaces[charts.chartFirstFace[c]];
    std::set<uint32_t> reached = {seed};
    std::vector<uint32_t> stack = {seed};
    while (!stack.empty()) {
        const uint32_t f = stack.back();
        stack.pop_back();
        for (int k = 0; k < 3; ++k) {
            const uint32_t o = adjacency.opposite[3 * f + k];
            if (o != kNoOpposite && charts.faceChart[o / 3] == c && reached.insert(o / 3).second)
                stack.push_back(o / 3);
        }
    }
    return reached.size();
}

}  // namespace

TEST(EdgeAdjacency, ClosedManifoldOpenAndNonManifold) {
    const TestMesh box = voxelBox(2, 2, 2);
    EdgeAdjacency a = buildEdgeAdjacency(box.triangles.data(), box.faceCount(), box.positions.size());
    EXPECT_EQ(a.borderEdges, 0u);
    EXPECT_EQ(a.nonManifoldEdges, 0u);
    for (size_t h = 0; h < a.opposite.size(); ++h) {
        ASSERT_NE(a.opposite[h], kNoOpposite);
        EXPECT_EQ(a.opposite[a.opposite[h]], h);
    }
    const TestMesh tri = singleTriangle();
    a = buildEdgeAdjacency(tri.triangles.data(), 1, 3);
    EXPECT_EQ(a.borderEdges, 3u);
    const TestMesh touching = edgeTouchingVoxels();
    a = buildEdgeAdjacency(touching.triangles.data(), touching.faceCount(), touching.positions.size());
    EXPECT_EQ(a.nonManifoldEdges, 1u);
}

TEST(Charts, FollowSection45OnEveryFamily) {
    for (float cone : {0.7f, 0.5f}) {
        for (const TestMesh &mesh : families()) {
            SCOPED_TRACE(mesh.name + " cone " + std::to_string(cone));
            ChartOptions options;
            options.minSeedCosine = cone;
            options.mergeFaces = 0;  // the paper's charts (merging: SmallChartsMoveIntoTheirNeighbours)
            const AtlasCharts charts = computeCharts(mesh.view(), options);
            ASSERT_EQ(charts.chartFaces.size(), mesh.faceCount());
            float lastPriority = 2;
            for (size_t c = 0; c < charts.chartCount(); ++c) {
                const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
                ASSERT_LT(first, end);
                if (charts.isDegenerate(c)) {
                    EXPECT_EQ(end - first, 1u);
                    continue;
                }
                // Seeds come most axis-aligned first.
                const glm::vec3 axis = charts.chartAxis[c];
                const float priority = std::max({std::abs(axis.x), std::abs(axis.y), std::abs(axis.z)});
                EXPECT_LE(priority, lastPriority);
                lastPriority = priority;
                EXPECT_GT(glm::dot(glm::dvec3(axis), geometricNormal(mesh, charts.chartFaces[first])), 1 - 1e-6);
                // Every face within the seed's cone; the chart edge-connected.
                std::set<std::pair<uint32_t, uint32_t>> edges;
                for (uint32_t i = first; i < end; ++i) {
                    const uint32_t f = charts.chartFaces[i];
                    EXPECT_EQ(charts.faceChart[f], c);
                    EXPECT_GE(glm::dot(glm::dvec3(axis), geometricNormal(mesh, f)), cone - 1e-6);
                    bool touches = i == first;
                    for (int k = 0; k < 3; ++k) {
                        uint32_t a = mesh.triangles[3 * f + k], b = mesh.triangles[3 * f + (k + 1) % 3];
                        if (a > b)
                            std::swap(a, b);
                        touches = touches || edges.count({a, b});
                    }
                    EXPECT_TRUE(touches) << "face " << f << " is not next to an earlier face of chart " << c;
                    for (int k = 0; k < 3; ++k) {
                        uint32_t a = mesh.triangles[3 * f + k], b = mesh.triangles[3 * f + (k + 1) % 3];
                        edges.insert({std::min(a, b), std::max(a, b)});
                    }
                }
            }
        }
    }
}

// Beyond the paper (chart_merge.h): charts of at most mergeFaces faces move whole into a
// neighbour whose axis is within mergeCosine of all their faces. Fewer charts on every family,
// each still edge-connected, every face within the wider cone, the unmerged faces' UVs unchanged
// (up to the chart's shift), and no overlap once packed.
TEST(Charts, SmallChartsMoveIntoTheirNeighbours) {
    size_t before = 0, after = 0;
    for (const TestMesh &mesh : families()) {
        SCOPED_TRACE(mesh.name);
        ChartOptions off;
        off.mergeFaces = 0;
        const AtlasCharts paper = computeCharts(mesh.view(), off), charts = computeCharts(mesh.view());
        EXPECT_EQ(paper.mergedCharts, 0u);
        EXPECT_EQ(charts.chartCount() + charts.mergedCharts, paper.chartCount());
        before += paper.chartCount();
        after += charts.chartCount();
        const EdgeAdjacency adjacency =
            buildEdgeAdjacency(mesh.triangles.data(), mesh.faceCount(), mesh.positions.size());
        for (size_t c = 0; c < charts.chartCount(); ++c) {
            const uint32_t first = charts.chartFirstFace[c], end = charts.chartFirstFace[c + 1];
            if (charts.isDegenerate(c))
                continue;
            EXPECT_EQ(facesReached(charts, adjacency, c), end - first) << "chart " << c << " is not edge-connected";
            const uint32_t seed = charts.chartFaces[first];
            EXPECT_EQ(paper.chartAxis[paper.faceChart[seed]], charts.chartAxis[c]);
            for (uint32_t i = first; i < end; ++i) {
                const uint32_t f = charts.chartFaces[i];
                EXPECT_GE(glm::dot(glm::dvec3(charts.chartAxis[c]), geometricNormal(mesh, f)), kMergeCone - 1e-6);
                // A face charted with the seed keeps its UVs up to one shift for the whole chart.
                if (paper.faceChart[f] != paper.faceChart[seed])
                    continue;
                const uint32_t j = paper.chartFirstFace[paper.faceChart[f]] + (i - first);
                ASSERT_EQ(paper.chartFaces[j], f);
                const glm::vec2 shift = charts.wedgeUv[3 * size_t(first)] -
                                        paper.wedgeUv[3 * size_t(paper.chartFirstFace[paper.faceChart[f]])];
                for (int k = 0; k < 3; ++k)
                    EXPECT_LE(glm::length(charts.wedgeUv[3 * size_t(i) + k] - paper.wedgeUv[3 * size_t(j) + k] - shift),
                              1e-3f);
            }
        }
        expectValidAtlas(mesh, charts, packCharts(charts), kMergeCone);
    }
    EXPECT_LT(after, before);
}

// Flat cells (i, j) of an n x n grid for which `in` holds, as two triangles each, in the plane
// turned by `turn` and moved by `offset`: one chart, whatever its shape.
TestMesh planarCells(const std::string &name, int n, const std::function<bool(int, int)> &in, const glm::dmat3 &turn,
                     const glm::dvec3 &offset) {
    TestMesh m;
    m.name = name;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.push_back(glm::vec3(turn * glm::dvec3(i, j, 0) + offset));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (in(i, j)) {
                const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1) + 1, d = c - 1;
                m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
                m.faceColours.push_back({uint8_t(i), uint8_t(j), 9});
                m.faceColours.push_back({uint8_t(i), uint8_t(j), 9});
            }
    computeVertexColours(m);
    return m;
}

// Rings (square frames), diagonal staircases and L shapes of random sizes in random planes
// (fixed seed): the one chart each makes is cut when it covers under 1/8 of its box, into pieces
// that cover at least 1/8 of theirs (or are single faces), each edge-connected, every face in
// exactly one, its UVs those of the uncut chart up to one shift per piece; a compact chart with a
// hole stays whole.
TEST(Charts, SparseChartsAreCutIntoCompactPieces) {
    std::mt19937_64 random(20261126);
    std::uniform_int_distribution<int> widthOf(1, 2), extra(0, 30);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    std::vector<TestMesh> sparse;
    for (int k = 0; k < 4; ++k) {
        // At least 36 widths long: a ring covers under 4 w / n = 1/9 of its box, an L or a staircase less.
        const int w = widthOf(random), n = 36 * w + extra(random);
        const glm::dmat3 turn = glm::dmat3(glm::rotate(glm::dmat4(1.0), angle(random), glm::dvec3(0.3, 1.0, 0.2))) *
                                glm::dmat3(glm::rotate(glm::dmat4(1.0), angle(random), glm::dvec3(1.0, 0.0, 0.4)));
        const glm::dvec3 offset(angle(random), angle(random), angle(random));
        sparse.push_back(planarCells(
            "ring " + std::to_string(k), n, [n, w](int i, int j) { return i < w || j < w || i >= n - w || j >= n - w; },
            turn, offset));
        sparse.push_back(planarCells(
            "staircase " + std::to_string(k), n, [w](int i, int j) { return j >= i && j < i + w + 1; }, turn, offset));
        sparse.push_back(planarCells(
            "L " + std::to_string(k), n, [w](int i, int j) { return i < w || j < w; }, turn, offset));
    }
    for (const TestMesh &mesh : sparse) {
        SCOPED_TRACE(mesh.name);
        ChartOptions whole;
        whole.minChartFill = 0;
        const AtlasCharts before = computeCharts(mesh.view(), whole), after = computeCharts(mesh.view());
        ASSERT_EQ(before.chartCount(), 1u);
        // Cut exactly when the chart covers under 1/8 of its box in its own projection (a
        // staircase the projection happens to lay along an axis is compact there).
        double chartArea = 0;
        for (size_t i = 0; i < before.chartFaces.size(); ++i) {
            const glm::vec2 *uv = &before.wedgeUv[3 * i];
            chartArea += 0.5 * std::fabs(doubleArea(uv[0], uv[1], uv[2]));
        }
        const bool isSparse = chartArea < 0.125 * double(before.chartSize[0].x) * double(before.chartSize[0].y);
        EXPECT_TRUE(isSparse || mesh.name.rfind("staircase", 0) == 0);
        EXPECT_EQ(after.splitCharts, isSparse ? 1u : 0u);
        EXPECT_EQ(after.chartCount() > 1, isSparse);
        std::vector<int> seen(mesh.faceCount(), 0);
        std::vector<uint32_t> entryBefore(mesh.faceCount());
        for (size_t i = 0; i < before.chartFaces.size(); ++i)
            entryBefore[before.chartFaces[i]] = uint32_t(i);
        const EdgeAdjacency adjacency =
            buildEdgeAdjacency(mesh.triangles.data(), mesh.faceCount(), mesh.positions.size());
        for (size_t c = 0; c < after.chartCount(); ++c) {
            const uint32_t first = after.chartFirstFace[c], end = after.chartFirstFace[c + 1];
            glm::vec2 lo(1e30f), hi(-1e30f);
            double area = 0;
            for (uint32_t i = first; i < end; ++i) {
                const uint32_t f = after.chartFaces[i];
                ++seen[f];
                EXPECT_EQ(after.faceChart[f], c);
                const glm::vec2 *uv = &after.wedgeUv[3 * size_t(i)];
                for (int k = 0; k < 3; ++k)
                    lo = glm::min(lo, uv[k]), hi = glm::max(hi, uv[k]);
                area += 0.5 * std::fabs(doubleArea(uv[0], uv[1], uv[2]));
                // The uncut chart's UVs, shifted alike for the whole piece.
                const uint32_t j = entryBefore[f];
                const glm::vec2 shift =
                    after.wedgeUv[3 * size_t(first)] - before.wedgeUv[3 * size_t(entryBefore[after.chartFaces[first]])];
                for (int k = 0; k < 3; ++k)
                    EXPECT_LE(glm::length(uv[k] - before.wedgeUv[3 * size_t(j) + k] - shift), 1e-4f);
            }
            EXPECT_LE(glm::length(lo), 1e-4f) << "piece " << c << " is not at the origin";
            EXPECT_LE(glm::length(hi - after.chartSize[c]), 1e-4f);
            EXPECT_TRUE(end - first == 1 || area >= 0.125 * double(hi.x - lo.x) * double(hi.y - lo.y) - 1e-6)
                << "piece " << c << " covers " << area / (double(hi.x - lo.x) * double(hi.y - lo.y));
            EXPECT_EQ(facesReached(after, adjacency, c), end - first) << "piece " << c << " is not edge-connected";
        }
        for (size_t f = 0; f < mesh.faceCount(); ++f)
            EXPECT_EQ(seen[f], 1) << "face " << f;
        expectValidAtlas(mesh, after, packCharts(after), ChartOptions().minSeedCosine);
    }
    // A 12 x 12 square with a 4 x 4 hole covers 8/9 of its box: one chart, as before.
    const TestMesh holed = planarCells(
        "holed square", 12, [](int i, int j) { return !(i >= 4 && i < 8 && j >= 4 && j < 8); }, glm::dmat3(1.0),
        glm::dvec3(0.0));
    const AtlasCharts charts = computeCharts(holed.view());
    EXPECT_EQ(charts.chartCount(), 1u);
    EXPECT_EQ(charts.splitCharts, 0u);
}

TEST(Charts, RawVoxelSurfacesSplitIntoPlanarRegions) {
    const TestMesh box = voxelBox(4, 3, 2);
    const AtlasCharts charts = computeCharts(box.view());
    EXPECT_EQ(charts.chartCount(), 6u);  // one per side of the box
    const TestMesh sphere = voxelSphere(6);
    const AtlasCharts sc = computeCharts(sphere.view());
    for (size_t f = 0; f < sphere.faceCount(); ++f)
        EXPECT_EQ(glm::vec3(geometricNormal(sphere, f)), sc.chartAxis[sc.faceChart[f]]);
}

TEST(Charts, AChartWindingOverItselfIsCutBack) {
    const TestMesh ramp = helicalRamp();
    const AtlasCharts charts = computeCharts(ramp.view());
    EXPECT_GT(charts.foldedCharts, 0u);
    EXPECT_GE(charts.chartCount(), 2u);
    const AtlasLayout layout = packCharts(charts);
    expectValidAtlas(ramp, charts, layout, kMergeCone);  // includes: no texel centre under two faces
}

// The first pass's fold checks run on two threads after the charts are grown (larger meshes):
// with a chart that folds among others before and after it, the charts must be those of the
// one-thread pass (grown and checked one by one).
TEST(Charts, FoldChecksOnThreadsGiveTheSameCharts) {
    TestMesh mesh = smoothed(voxelSphere(14));
    const TestMesh ramp = helicalRamp();
    for (int copy = 0; copy < 4; ++copy) {  // ramps side by side: above the parallel threshold
        const uint32_t base = uint32_t(mesh.positions.size());
        for (const glm::vec3 &p : ramp.positions)
            mesh.positions.push_back(p + glm::vec3(40.0f + 12.0f * float(copy), 0.0f, 0.0f));
        for (uint32_t v : ramp.triangles)
            mesh.triangles.push_back(base + v);
        mesh.faceColours.insert(mesh.faceColours.end(), ramp.faceColours.begin(), ramp.faceColours.end());
        mesh.vertexColours.insert(mesh.vertexColours.end(), ramp.vertexColours.begin(), ramp.vertexColours.end());
    }
    ASSERT_GE(mesh.faceCount(), 4096u);
    ChartOptions one;
    one.threads = 1;
    const AtlasCharts reference = computeCharts(mesh.view(), one);
    EXPECT_GT(reference.foldedCharts, 0u);
    for (int threads : {2, 5}) {
        ChartOptions options;
        options.threads = threads;
        expectSameCharts(computeCharts(mesh.view(), options), reference, threads);
    }
}

// The faces' normals are computed on both threads (the last fifth on the second, beside the edge
// adjacency): with non-finite vertices, zero-area faces and given normals (some pointing away, so
// ignored) in both parts, the charts and their counts are those of one thread.
TEST(Charts, NormalsOnTwoThreadsGiveTheSameChartsAndCounts) {
    TestMesh mesh = smoothed(voxelSphere(16));
    const size_t faces = mesh.faceCount();
    ASSERT_GE(faces, 4096u);
    std::vector<glm::vec3> given(faces);
    for (size_t f = 0; f < faces; ++f) {
        const uint32_t *t = &mesh.triangles[3 * f];
        given[f] = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
        if (f % 97 == 0)
            given[f] = -given[f];  // outside the face's own cone: ignored
    }
    for (const size_t f : {size_t(10), faces / 2, faces - faces / 10, faces - 3}) {
        mesh.positions[mesh.triangles[3 * f]] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
        mesh.triangles[3 * (f + 1) + 2] = mesh.triangles[3 * (f + 1) + 1];  // zero area
    }
    AtlasMesh view = mesh.view();
    view.faceNormals = given.data();
    ChartOptions one;
    one.threads = 1;
    const AtlasCharts reference = computeCharts(view, one);
    EXPECT_GT(reference.nonFiniteFaces, 0u);
    EXPECT_GT(reference.degenerateFaces, reference.nonFiniteFaces);
    EXPECT_GT(reference.ignoredNormals, 0u);
    for (int threads : {2, 5}) {
        ChartOptions options;
        options.threads = threads;
        const AtlasCharts charts = computeCharts(view, options);
        EXPECT_EQ(charts.chartFaces, reference.chartFaces) << threads << " threads";
        EXPECT_EQ(charts.chartFirstFace, reference.chartFirstFace) << threads << " threads";
        EXPECT_EQ(charts.wedgeUv, reference.wedgeUv) << threads << " threads";
        EXPECT_EQ(charts.chartAxis, reference.chartAxis) << threads << " threads";
        EXPECT_EQ(charts.nonFiniteFaces, reference.nonFiniteFaces) << threads << " threads";
        EXPECT_EQ(charts.degenerateFaces, reference.degenerateFaces) << threads << " threads";
        EXPECT_EQ(charts.ignoredNormals, reference.ignoredNormals) << threads << " threads";
    }
}

// Two faces at one vertex whose sectors overlap (the chart went round the vertex past a gap)
// fold the chart though no two boundary edges cross; a full fan of six does not.
TEST(Charts, SectorsOverlappingAtAVertexAreAFold) {
    const double sixth = 6.283185307179586 / 6;
    std::vector<ChartCorner> fan;
    for (int k = 0; k < 6; ++k)
        fan.push_back({7, k * sixth, sixth});
    EXPECT_FALSE(cornersOverlap(fan));
    std::vector<ChartCorner> overlapping = {{3, 4.2, 0.7}, {3, 4.83, 0.7}, {5, 0.0, 3.0}};
    EXPECT_TRUE(cornersOverlap(overlapping));
    std::vector<ChartCorner> pastTheTurn = {{3, 0.1, 1.0}, {3, 5.5, 1.0}};
    EXPECT_TRUE(cornersOverlap(pastTheTurn));
}

// Many corners (past the few that are insertion-sorted) at vertices whose ids differ in every
// byte, given in shuffled order: closed fans do not fold; one sector pushed past its neighbour's
// start at one vertex does, as does one wrapped past the full turn at another.
TEST(Charts, SectorsOverlapAmongManyCornersInAnyOrder) {
    const double sixth = 6.283185307179586 / 6;
    const uint32_t vertices[] = {0, 255, 256, 70000, 16777216, 4000000000u};
    std::vector<ChartCorner> fans;
    for (const uint32_t v : vertices)
        for (int k = 0; k < 6; ++k)
            fans.push_back({v, k * sixth, sixth});
    std::mt19937 random(14);
    for (int round = 0; round < 20; ++round) {
        std::shuffle(fans.begin(), fans.end(), random);
        std::vector<ChartCorner> corners = fans;
        EXPECT_FALSE(cornersOverlap(corners));
        ASSERT_EQ(corners.size(), fans.size());
        std::vector<ChartCorner> pushed = fans;
        for (ChartCorner &c : pushed)
            if (c.vertex == 70000 && c.from > 2 * sixth && c.from < 3.5 * sixth)
                c.width += 0.01;  // over the next sector's start
        EXPECT_TRUE(cornersOverlap(pushed));
        std::vector<ChartCorner> wrapped = fans;
        for (ChartCorner &c : wrapped)
            if (c.vertex == 4000000000u && c.from > 4.5 * sixth)
                c.width += 0.01;  // past the full turn into the first sector
        EXPECT_TRUE(cornersOverlap(wrapped));
    }
}

TEST(Charts, UnsharedCornersAreMatchedByPosition) {
    const TestMesh welded = smoothed(voxelSphere(6));
    TestMesh loose = welded;  // three vertices of its own per triangle, as in an STL file
    loose.positions.clear();
    loose.triangles.clear();
    for (uint32_t v : welded.triangles) {
        loose.triangles.push_back(uint32_t(loose.positions.size()));
        loose.positions.push_back(welded.positions[v]);
    }
    computeVertexColours(loose);
    const AtlasCharts a = computeCharts(welded.view()), b = computeCharts(loose.view());
    EXPECT_FALSE(a.weldedByPosition);
    EXPECT_TRUE(b.weldedByPosition);
    EXPECT_EQ(a.faceChart, b.faceChart);
    expectValidAtlas(loose, b, packCharts(b), kMergeCone);
}

TEST(Charts, WiderConeGivesFewerCharts) {
    const TestMesh sphere = smoothed(voxelSphere(12));
    ChartOptions paperText;
    paperText.minSeedCosine = 0.5f;  // the paper's 60 degrees
    EXPECT_LT(computeCharts(sphere.view(), paperText).chartCount(), computeCharts(sphere.view()).chartCount());
}

TEST(Charts, DegenerateAndNonFiniteFacesGetTheirOwnTinyCharts) {
    TestMesh mesh = boxWithZeroAreaFaces();
    mesh.positions.push_back({std::numeric_limits<float>::quiet_NaN(), 0, 0});
    mesh.triangles.insert(mesh.triangles.end(), {0, 1, uint32_t(mesh.positions.size() - 1)});
    mesh.faceColours.push_back({1, 2, 3});
    const AtlasCharts charts = computeCharts(mesh.view(false, false));
    EXPECT_EQ(charts.degenerateFaces, 4u);
    EXPECT_EQ(charts.nonFiniteFaces, 1u);
    for (size_t f = mesh.faceCount() - 4; f < mesh.faceCount(); ++f)
        EXPECT_TRUE(charts.isDegenerate(charts.faceChart[f]));
    const AtlasLayout layout = packCharts(charts);
    EXPECT_EQ(measureAtlas(mesh.view(), charts, layout).facesWithoutUvArea, 0u);
}

TEST(Charts, GivenNormalsDriveTheConeButNeverFoldAFace) {
    const TestMesh sphere = smoothed(voxelSphere(8));
    std::vector<glm::vec3> normals(sphere.faceCount());
    for (size_t f = 0; f < normals.size(); ++f)
        normals[f] = glm::vec3(geometricNormal(sphere, f)) * 3.0f;  // any length
    normals[5] = -normals[5];                                       // unusable: ignored
    normals[7] = glm::vec3(0.0f);
    AtlasMesh view = sphere.view();
    view.faceNormals = normals.data();
    const AtlasCharts given = computeCharts(view);
    EXPECT_EQ(given.ignoredNormals, 2u);
    expectValidAtlas(sphere, given, packCharts(given), kMergeCone);

    // Normals snapped to the nearest axis where that stays in the face's cone: other seeds and
    // cones, yet the geometric test keeps every face within the stretch bound.
    for (size_t f = 0; f < normals.size(); ++f) {
        const glm::dvec3 n = geometricNormal(sphere, f);
        const int axis = std::abs(n.x) >= std::max(std::abs(n.y), std::abs(n.z)) ? 0
                         : std::abs(n.y) >= std::abs(n.z)                        ? 1
                                                                                 : 2;
        glm::vec3 snapped(0.0f);
        snapped[axis] = n[axis] > 0 ? 1.0f : -1.0f;
        normals[f] = std::abs(n[axis]) >= 0.75 ? snapped : glm::vec3(n);
    }
    const AtlasCharts snapped = computeCharts(view);
    EXPECT_EQ(snapped.ignoredNormals, 0u);
    EXPECT_NE(snapped.faceChart, computeCharts(sphere.view()).faceChart);
    expectValidAtlas(sphere, snapped, packCharts(snapped), kMergeCone);
}

TEST(Packing, EveryFamilyEveryModeIsValid) {
    for (const TestMesh &mesh : families())
        for (PackMode mode : {PackMode::Paper, PackMode::Tight}) {
            const AtlasCharts charts = computeCharts(mesh.view());
            PackOptions density;
            density.mode = mode;
            density.texelsPerUnit = 8;
            const AtlasLayout byDensity = packCharts(charts, density);
            expectValidAtlas(mesh, charts, byDensity, kMergeCone);
            EXPECT_FALSE(byDensity.densityReduced);
            // The density is a minimum, raised to fill the texture (tight packing).
            EXPECT_GE(byDensity.texelsPerUnit, 8.0);
            if (mode == PackMode::Paper) {
                EXPECT_EQ(byDensity.texelsPerUnit, 8.0);
            }
            for (int side : {byDensity.width, byDensity.height})
                EXPECT_EQ(side & (side - 1), 0) << "not a power of two: " << side;
            EXPECT_TRUE(byDensity.width == byDensity.height || byDensity.width == 2 * byDensity.height)
                << byDensity.width << " x " << byDensity.height;
            EXPECT_EQ(byDensity.size, byDensity.width);

            // The same texture at the least density: the fill only raised it (without the
            // small-texture step).
            PackOptions sameSize = density;
            sameSize.leastChartShare = 0;
            const AtlasLayout filled = packCharts(charts, sameSize);
            PackOptions least = density;
            least.fillTexture = false;
            const AtlasLayout atLeast = packCharts(charts, least);
            expectValidAtlas(mesh, charts, atLeast, kMergeCone);
            EXPECT_EQ(atLeast.texelsPerUnit, 8.0);
            EXPECT_EQ(atLeast.width, filled.width);
            EXPECT_EQ(atLeast.height, filled.height);
            // The step: a larger texture only while small, and only for a denser fill of it.
            const double texels = double(byDensity.width) * byDensity.height;
            if (texels != double(filled.width) * filled.height) {
                EXPECT_LE(texels, double(density.smallTexels));
                EXPECT_GT(byDensity.texelsPerUnit * byDensity.texelsPerUnit / texels,
                          filled.texelsPerUnit * filled.texelsPerUnit / (double(filled.width) * filled.height));
            }

            PackOptions fixed = density;
            fixed.textureSize = 256;
            const AtlasLayout bySize = packCharts(charts, fixed);
            expectValidAtlas(mesh, charts, bySize, kMergeCone);
            EXPECT_EQ(bySize.size, 256);
        }
}

TEST(Packing, WiderConeKeepsItsStretchBound) {
    const TestMesh mesh = smoothed(voxelBlob(9, 3));
    ChartOptions options;
    options.minSeedCosine = 0.5f;
    const AtlasCharts charts = computeCharts(mesh.view(), options);
    expectValidAtlas(mesh, charts, packCharts(charts), 0.5f);
}

TEST(Packing, StretchIsOneOverTheCosineToTheSeed) {
    // A hinge at 30 degrees: one chart (cos 30 >= 0.7); the second face is shrunk by cos 30.
    TestMesh m;
    m.name = "hinge";
    const float s = std::sin(0.5236f), c = std::cos(0.5236f);
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}, {2 + 2 * c, 2, 2 * s}};
    m.triangles = {0, 1, 3, 0, 3, 2, 1, 4, 3};
    m.faceColours = {{1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    const AtlasCharts charts = computeCharts(m.view());
    ASSERT_EQ(charts.chartCount(), 1u);
    const AtlasMeasures measures = measureAtlas(m.view(), charts, packCharts(charts));
    EXPECT_NEAR(measures.maxStretch, 1.0, 1e-4);
    EXPECT_NEAR(measures.maxInverseStretch, 1.0 / c, 1e-4);
}

TEST(Packing, TightFillsTheReferenceSphereBeyondSeventyPercent) {
    // The project's reference: a Taubin-smoothed voxel sphere of radius 20 in 1024^2.
    const TestMesh sphere = smoothed(voxelSphere(20));
    const AtlasCharts charts = computeCharts(sphere.view());
    PackOptions tight;
    tight.textureSize = 1024;
    const AtlasLayout layout = packCharts(charts, tight);
    const AtlasMeasures m = measureAtlas(sphere.view(), charts, layout);
    EXPECT_GE(m.packingEfficiency, 0.70);
    EXPECT_EQ(m.overlappingChartTexels, 0u);
    PackOptions paper = tight;
    paper.mode = PackMode::Paper;
    const AtlasLayout paperLayout = packCharts(charts, paper);
    EXPECT_LT(measureAtlas(sphere.view(), charts, paperLayout).packingEfficiency, m.packingEfficiency);
    EXPECT_LT(paperLayout.texelsPerUnit, layout.texelsPerUnit);
}

// A chart's mask holds its footprint and padding and nothing more: a flat rectangle of random
// sizes, offsets and densities touches ceil(length + the masks' two 1/256-texel margins) texels
// per side, the least any placement can (its box once started exactly on a texel boundary,
// where the margin took the whole row and column before it).
TEST(Packing, AMaskIsNoLargerThanItsChart) {
    std::mt19937_64 random(20261126);
    std::uniform_real_distribution<double> size(0.5, 12.0), offset(-50.0, 50.0), density(1.0, 16.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec2 s(size(random), size(random));
        const glm::dvec2 o(offset(random), offset(random));
        const std::vector<glm::vec3> positions = {
            {o.x, o.y, 0}, {o.x + s.x, o.y, 0}, {o.x + s.x, o.y + s.y, 0}, {o.x, o.y + s.y, 0}};
        const std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
        AtlasMesh mesh;
        static_cast<TriangleMesh &>(mesh) = triangleMesh(positions, triangles);
        const AtlasCharts charts = computeCharts(mesh);
        ASSERT_EQ(charts.chartCount(), 1u);
        const double d = density(random);
        for (int padding : {1, 2}) {
            ChartMasks masks;
            ASSERT_TRUE(rasterizeChartMasks(charts, d, padding, 4096, masks));
            const glm::dvec2 texels = glm::dvec2(charts.chartSize[0]) * d + 2.0 / 256;
            for (int axis = 0; axis < 2; ++axis) {
                const double fraction = texels[axis] - std::floor(texels[axis]);
                if (fraction < 2.0 / 256 || fraction > 1 - 2.0 / 256)
                    continue;  // float UVs decide which way it rounds
                const int footprint = axis == 0 ? masks.charts[0].width : masks.charts[0].height;
                EXPECT_EQ(footprint - 2 * padding, int(std::ceil(texels[axis])))
                    << "size " << s.x << " x " << s.y << " at " << d << " texels per unit, axis " << axis;
            }
        }
    }
}

TEST(Packing, PaperSquareIsCentred) {
    const TestMesh mesh = smoothed(voxelSphere(8));
    const AtlasCharts charts = computeCharts(mesh.view());
    PackOptions paper;
    paper.mode = PackMode::Paper;
    paper.textureSize = 512;
    const AtlasLayout layout = packCharts(charts, paper);
    glm::vec2 lo(1), hi(0);
    for (const glm::vec2 &uv : layout.wedgeUv)
        lo = glm::min(lo, uv), hi = glm::max(hi, uv);
    const glm::vec2 margin = lo + hi - 1.0f;  // 0 when centred
    EXPECT_NEAR(margin.x, 0.0f, 8.0f / 512);
    EXPECT_NEAR(margin.y, 0.0f, 8.0f / 512);
}

TEST(Packing, DensityIsLoweredToFitTheLargestTexture) {
    const TestMesh mesh = smoothed(voxelSphere(10));
    const AtlasCharts charts = computeCharts(mesh.view());
    PackOptions options;
    options.texelsPerUnit = 64;
    options.maxTextureSize = 256;
    const AtlasLayout layout = packCharts(charts, options);
    expectValidAtlas(mesh, charts, layout, kMergeCone);
    EXPECT_TRUE(layout.densityReduced);
    EXPECT_FALSE(layout.note.empty());
    EXPECT_EQ(layout.size, 256);
    EXPECT_LT(layout.texelsPerUnit, 64.0);
}

TEST(Packing, IsDeterministic) {
    const TestMesh mesh = smoothed(voxelBlob(8, 5));
    const AtlasCharts charts = computeCharts(mesh.view());
    EXPECT_EQ(packCharts(charts).wedgeUv, packCharts(charts).wedgeUv);
}

// Masks, bitmaps, the large charts' turns and the bake run on threads; the result must not depend on how many.
TEST(Packing, ThreadCountChangesNothing) {
    const TestMesh mesh = smoothed(voxelSphere(20));  // ~10k faces: above the parallel thresholds
    ASSERT_GE(mesh.faceCount(), 4096u);
    for (BakeSource source : {BakeSource::FaceColours, BakeSource::VertexColours}) {
        for (int dilation : {-1, 2}) {
            SCOPED_TRACE(std::string(toString(source)) + ", dilation " + std::to_string(dilation));
            TextureAtlas reference;
            for (int threads : {1, 2, 5}) {
                AtlasOptions options;
                options.pack.texelsPerUnit = 8;
                options.pack.threads = threads;
                options.bake.threads = threads;
                options.bake.source = source;
                options.bake.dilation = dilation;
                const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
                if (threads == 1) {
                    reference = atlas;
                    continue;
                }
                EXPECT_EQ(atlas.layout.wedgeUv, reference.layout.wedgeUv) << threads << " threads";
                EXPECT_EQ(atlas.texture.rgba, reference.texture.rgba) << threads << " threads";
            }
        }
    }
}

TEST(Bake, CrispColoursSurviveNearestAndBilinearSampling) {
    for (const TestMesh &mesh : families()) {
        SCOPED_TRACE(mesh.name);
        const TextureAtlas atlas = atlasAt(mesh, 16);
        EXPECT_EQ(atlas.texture.source, BakeSource::FaceColours);
        const ColourFidelity f = measureColourFidelity(mesh.view(), atlas.layout, atlas.texture);
        EXPECT_EQ(f.guaranteedNearestMatches, f.guaranteedNearest);
        EXPECT_EQ(f.guaranteedBilinearMatches, f.guaranteedBilinear);
        // At 16 texels per voxel even the faces Taubin shrinks most keep their colour under
        // nearest sampling; bilinear filtering may blend in a neighbour on a few of them (and on
        // the ramp's thin faces, which are not voxel faces).
        EXPECT_EQ(f.nearestMatches, f.samples);
        if (mesh.name != "helical ramp") {
            EXPECT_GE(f.bilinear(), 0.99);
        }
    }
}

TEST(Bake, DilationFillsExactlyTheRequestedRings) {
    const TestMesh mesh = smoothed(voxelSphere(6));
    for (int rings : {1, 2, 3}) {
        AtlasOptions options;
        options.pack.gutter = 2 * rings;
        options.pack.mipBlocks = false;  // (blocks fill more: MipBlocksHoldOneChartEach)
        options.bake.dilation = rings;
        const TextureAtlas atlas = buildTextureAtlas(mesh.view(), options);
        const int size = atlas.texture.width, height = atlas.texture.height;
        std::vector<uint8_t> covered(size_t(size) * height, 0);
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            glm::dvec2 q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = glm::dvec2(atlas.layout.wedgeUv[3 * f + k]) * glm::dvec2(size, height);
            rasterConservative(q[0], q[1], q[2], -1.0 / 256, size, height,
                               [&](int x, int y) { covered[size_t(y) * size + x] = 1; });
        }
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < size; ++x) {
                int distance = INT32_MAX;  // Chebyshev distance to the nearest covered texel
                for (int dy = -rings - 1; dy <= rings + 1; ++dy)
                    for (int dx = -rings - 1; dx <= rings + 1; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u >= 0 && v >= 0 && u < size && v < height && covered[size_t(v) * size + u])
                            distance = std::min(distance, std::max(std::abs(dx), std::abs(dy)));
                    }
                const uint8_t alpha = atlas.texture.texel(x, y).a;
                ASSERT_EQ(alpha, distance <= rings ? 255 : 0) << x << "," << y << " at distance " << distance;
            }
    }
}

// The default layout on 2 x 2 blocks: every block within one texel of a chart's texels is
// opaque and near no other chart, so a box-filtered mip level 1, sampled bilinearly anywhere in a
// chart, reads that chart's colours only; on every family, with a gutter of 2.
TEST(Bake, MipBlocksHoldOneChartEach) {
    for (const TestMesh &mesh : families()) {
        SCOPED_TRACE(mesh.name);
        const TextureAtlas atlas = atlasAt(mesh, 8);
        ASSERT_EQ(atlas.layout.block, 2);
        ASSERT_EQ(atlas.layout.gutter, 2);
        const int width = atlas.texture.width, height = atlas.texture.height;
        ASSERT_EQ(width % 2, 0);
        ASSERT_EQ(height % 2, 0);
        for (const ChartPlacement &p : atlas.layout.placements)
            ASSERT_TRUE(p.x % 2 == 0 && p.y % 2 == 0);
        // Per block: the chart whose texels (grown by one) reach it, -1 none, -2 two charts.
        std::vector<int> owner(size_t(width / 2) * size_t(height / 2), -1);
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            glm::dvec2 q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = glm::dvec2(atlas.layout.wedgeUv[3 * f + k]) * glm::dvec2(width, height);
            const int chart = int(atlas.charts.faceChart[f]);
            rasterConservative(q[0], q[1], q[2], -1.0 / 256, width, height, [&](int x, int y) {
                for (int v = std::max(0, y - 1); v <= std::min(height - 1, y + 1); ++v)
                    for (int u = std::max(0, x - 1); u <= std::min(width - 1, x + 1); ++u) {
                        int &o = owner[size_t(v / 2) * size_t(width / 2) + size_t(u / 2)];
                        o = o == -1 || o == chart ? chart : -2;
                    }
            });
        }
        for (int by = 0; by < height / 2; ++by)
            for (int bx = 0; bx < width / 2; ++bx) {
                const int o = owner[size_t(by) * size_t(width / 2) + size_t(bx)];
                ASSERT_NE(o, -2) << "block " << bx << "," << by << " near two charts";
                if (o < 0)
                    continue;
                for (int k = 0; k < 4; ++k) {
                    ASSERT_EQ(atlas.texture.texel(2 * bx + k % 2, 2 * by + k / 2).a, 255)
                        << "block " << bx << "," << by << " not filled";
                }
            }
    }
}

TEST(Bake, GouraudStaysBetweenTheVertexColours) {
    const TestMesh mesh = smoothed(voxelSphere(6));
    AtlasOptions options;
    options.bake.source = BakeSource::VertexColours;
    const TextureAtlas atlas = atlasAt(mesh, 8, options);
    EXPECT_EQ(atlas.texture.source, BakeSource::VertexColours);
    const int size = atlas.texture.width, height = atlas.texture.height;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        glm::dvec2 q[3];
        glm::ivec3 lo(255), hi(0);
        for (int k = 0; k < 3; ++k) {
            q[k] = glm::dvec2(atlas.layout.wedgeUv[3 * f + k]) * glm::dvec2(size, height);
            const glm::ivec3 c = glm::ivec3(mesh.vertexColours[mesh.triangles[3 * f + k]]);
            lo = glm::min(lo, c), hi = glm::max(hi, c);
        }
        rasterCentres(q[0], q[1], q[2], size, height, [&](int x, int y) {
            const glm::ivec3 t = glm::ivec3(glm::u8vec3(atlas.texture.texel(x, y)));
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(t, lo - 1)) && glm::all(glm::lessThanEqual(t, hi + 1)));
        });
    }
}

TEST(Bake, FallsBackWhenColoursAreMissing) {
    const TestMesh mesh = voxelBox(2, 2, 2);
    AtlasTexture t = buildTextureAtlas(mesh.view(false, true)).texture;
    EXPECT_EQ(t.source, BakeSource::VertexColours);
    EXPECT_FALSE(t.note.empty());
    AtlasOptions gouraud;
    gouraud.bake.source = BakeSource::VertexColours;
    t = buildTextureAtlas(mesh.view(true, false), gouraud).texture;
    EXPECT_EQ(t.source, BakeSource::FaceColours);
    t = buildTextureAtlas(mesh.view(false, false)).texture;
    EXPECT_EQ(t.source, BakeSource::FlatColour);
    EXPECT_FALSE(t.note.empty());
    size_t opaque = 0;
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x)
            if (t.texel(x, y).a == 255) {
                ++opaque;
                EXPECT_EQ(glm::u8vec3(t.texel(x, y)), BakeOptions().flatColour);
            }
    EXPECT_GT(opaque, 0u);
}

// The message of the error of type E that `run` throws (a test failure when it throws none).
template <class E, class Run>
std::string thrownMessage(const Run &run) {
    try {
        run();
    } catch (const E &e) {
        return e.what();
    }
    ADD_FAILURE() << "no error thrown";
    return {};
}

TEST(BadInput, EmptyInvalidAndImpossibleRequestsGiveMessagesNotCrashes) {
    // No faces: an empty atlas, no error.
    AtlasMesh empty;
    TextureAtlas atlas = buildTextureAtlas(empty);
    EXPECT_EQ(atlas.charts.chartCount(), 0u);
    EXPECT_TRUE(atlas.layout.wedgeUv.empty());
    EXPECT_EQ(atlas.layout.width, 0);
    EXPECT_TRUE(atlas.texture.rgba.empty());

    const TestMesh box = voxelBox(2, 1, 1);
    AtlasMesh noPositions = box.view();
    noPositions.positions = nullptr;
    EXPECT_FALSE(thrownMessage<MeshError>([&] { buildTextureAtlas(noPositions); }).empty());

    std::vector<uint32_t> bad = box.triangles;
    bad[4] = 999;
    AtlasMesh outOfRange = box.view();
    outOfRange.triangles = bad.data();
    const std::string outOfRangeMessage = thrownMessage<MeshError>([&] { buildTextureAtlas(outOfRange); });
    EXPECT_NE(outOfRangeMessage.find("999"), std::string::npos) << outOfRangeMessage;
    EXPECT_NE(outOfRangeMessage.find("face 1"), std::string::npos) << outOfRangeMessage;

    const AtlasCharts charts = computeCharts(box.view());
    for (float density :
         {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        PackOptions options;
        options.texelsPerUnit = density;
        EXPECT_FALSE(thrownMessage<OptionError>([&] { packCharts(charts, options); }).empty());
    }
    // Thousands of charts cannot fit 8 x 8 texels at any density.
    const TestMesh sphere = voxelSphere(10);
    PackOptions tiny;
    tiny.textureSize = 8;
    const AtlasCharts sphereCharts = computeCharts(sphere.view());
    EXPECT_FALSE(thrownMessage<OptionError>([&] { packCharts(sphereCharts, tiny); }).empty());
    // A layout made for another mesh.
    const AtlasLayout boxLayout = packCharts(charts);
    EXPECT_FALSE(thrownMessage<MeshError>([&] { bakeTexture(sphere.view(), boxLayout); }).empty());
}

TEST(BadInput, NonManifoldEdgesAreChartBorders) {
    const TestMesh mesh = edgeTouchingVoxels();
    const AtlasCharts charts = computeCharts(mesh.view());
    EXPECT_EQ(charts.nonManifoldEdges, 1u);
    expectValidAtlas(mesh, charts, packCharts(charts), kMergeCone);
}
