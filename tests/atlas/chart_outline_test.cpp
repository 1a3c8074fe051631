// Chart outlines (atlas/chart_outline.h): the block masks filled from each chart's outline are
// those of rasterising every triangle, on families of meshes in random orientations, at densities
// from under one block per unit to many.
#include "atlas/chart_masks.h"
#include "atlas/chart_outline.h"
#include "atlas/charts.h"
#include "atlas/edge_adjacency.h"
#include "atlas/texel_raster.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

// Long thin slivers side by side, a fan around one vertex and a plate with a square hole: the
// shapes whose outlines have the most and the sharpest corners.
TestMesh slivers() {
    TestMesh m;
    m.name = "diagonal slivers";
    const int n = 24;
    for (int i = 0; i <= n; ++i) {
        m.positions.push_back({float(i) * 0.13f, 0, 0});
        m.positions.push_back({float(i) * 0.13f + 9.0f, 5.0f, 0});
    }
    for (int i = 0; i < n; ++i) {
        const uint32_t a = uint32_t(2 * i);
        m.triangles.insert(m.triangles.end(), {a, a + 2, a + 3, a, a + 3, a + 1});
        m.faceColours.push_back(voxelColour(i, 0, 0));
        m.faceColours.push_back(voxelColour(i, 1, 0));
    }
    computeVertexColours(m);
    return m;
}

TestMesh fan() {
    TestMesh m;
    m.name = "fan";
    m.positions.push_back({0, 0, 0});
    const int n = 40;
    for (int i = 0; i <= n; ++i) {
        const float t = 1.9f * 3.14159265f * float(i) / n;
        m.positions.push_back({6.0f * std::cos(t), 6.0f * std::sin(t), 0});
    }
    for (int i = 0; i < n; ++i) {
        m.triangles.insert(m.triangles.end(), {0, uint32_t(i + 1), uint32_t(i + 2)});
        m.faceColours.push_back(voxelColour(i, 0, 0));
    }
    computeVertexColours(m);
    return m;
}

TestMesh plateWithHole() {
    return voxelSurface("plate with a hole", 9, 9, 1,
                        [](int x, int y, int) { return !(x >= 3 && x <= 5 && y >= 3 && y <= 5); });
}

std::vector<TestMesh> families() {
    std::vector<TestMesh> out;
    out.push_back(voxelSphere(6));
    out.push_back(smoothed(voxelSphere(9)));
    out.push_back(smoothed(voxelBox(6, 4, 3), 5));
    out.push_back(smoothed(voxelTorus(8, 3)));
    out.push_back(smoothed(voxelBlob(8, 3), 4));
    out.push_back(slivers());
    out.push_back(fan());
    out.push_back(plateWithHole());
    return out;
}

TestMesh turned(TestMesh m, std::mt19937_64 &random) {
    std::uniform_real_distribution<float> angle(0.0f, 6.2831853f), axis(-1.0f, 1.0f), shift(-30.0f, 30.0f);
    glm::vec3 a(axis(random), axis(random), axis(random));
    if (glm::length(a) < 1e-3f)
        a = {0, 0, 1};
    const glm::mat4 r = glm::rotate(glm::translate(glm::mat4(1.0f), {shift(random), shift(random), shift(random)}),
                                    angle(random), glm::normalize(a));
    for (glm::vec3 &p : m.positions)
        p = glm::vec3(r * glm::vec4(p, 1.0f));
    return m;
}

// Whether the square [lo, hi] meets triangle t (separating axes: the square's two, the
// triangle's three edge normals); `slack` counts a gap up to it as meeting.
bool squareMeetsTriangle(glm::dvec2 lo, glm::dvec2 hi, const glm::dvec2 t[3], double slack) {
    const glm::dvec2 square[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    auto separated = [&](glm::dvec2 axis) {
        double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
        for (const glm::dvec2 &p : square)
            a0 = std::min(a0, glm::dot(axis, p)), a1 = std::max(a1, glm::dot(axis, p));
        for (int k = 0; k < 3; ++k)
            b0 = std::min(b0, glm::dot(axis, t[k])), b1 = std::max(b1, glm::dot(axis, t[k]));
        const double scale = std::max(1.0, glm::length(axis));
        return a1 < b0 - slack * scale || b1 < a0 - slack * scale;
    };
    if (separated({1, 0}) || separated({0, 1}))
        return false;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 e = t[(k + 1) % 3] - t[k];
        if (separated({-e.y, e.x}))
            return false;
    }
    return true;
}

}  // namespace

// Each shared edge is shared from both sides, never across a chart border.
TEST(ChartOutline, SharedEdgesAreMutualAndInsideTheirChart) {
    std::mt19937_64 random(20261127);
    for (const TestMesh &base : families()) {
        const TestMesh mesh = turned(base, random);
        const AtlasCharts charts = computeCharts(mesh.view());
        const std::vector<uint8_t> shared = chartOutlineBasis(charts).shared;
        ASSERT_EQ(shared.size(), charts.faceCount()) << mesh.name;
        std::vector<size_t> position(charts.faceCount());
        for (size_t i = 0; i < charts.faceCount(); ++i)
            position[charts.chartFaces[i]] = i;
        size_t count = 0;
        for (size_t i = 0; i < charts.faceCount(); ++i)
            for (int k = 0; k < 3; ++k) {
                if (!(shared[i] >> k & 1))
                    continue;
                ++count;
                const uint32_t f = charts.chartFaces[i], o = charts.faceOpposite[3 * size_t(f) + size_t(k)];
                ASSERT_NE(o, kNoOpposite) << mesh.name;
                EXPECT_EQ(charts.faceChart[o / 3], charts.faceChart[f]) << mesh.name;
                EXPECT_TRUE(shared[position[o / 3]] >> (o % 3) & 1) << mesh.name << ": shared from one side only";
            }
        EXPECT_GT(count, charts.faceCount()) << mesh.name << ": most edges lie inside their chart";
    }
}

// The masks with outlines against every triangle rasterised: never a block more, and a block
// less only where no triangle meets its grown square (the conservative test's corner blocks).
// The filled insides are the centres inside a triangle, checked one by one.
TEST(ChartOutline, BlockMasksMatchRasterisingEveryTriangle) {
    std::mt19937_64 random(77);
    size_t outlined = 0, fewer = 0, blocks = 0;
    for (const TestMesh &base : families())
        for (int turn = 0; turn < 3; ++turn) {
            const TestMesh mesh = turned(base, random);
            const AtlasCharts charts = computeCharts(mesh.view());
            const ChartOutlineBasis basis = chartOutlineBasis(charts);
            for (double density : {0.7, 1.9, 4.0, 8.0, 13.3})
                for (int padding : {1, 2}) {
                    ChartMasks all, outline;
                    ASSERT_TRUE(rasterizeChartMasks(charts, density, padding, 16384, all, 1, true));
                    ASSERT_TRUE(rasterizeChartMasks(charts, density, padding, 16384, outline, 1, true, &basis));
                    ASSERT_EQ(all.charts.size(), outline.charts.size());
                    const double margin = (padding + 1.0 / 256) / 2;
                    for (size_t c = 0; c < charts.chartCount(); ++c) {
                        const ChartMask &a = all.charts[c], &b = outline.charts[c];
                        ASSERT_EQ(a.width, b.width);
                        ASSERT_EQ(a.height, b.height);
                        ASSERT_EQ(a.offset, b.offset);
                        if (all.bitsFirst[c] == ChartMasks::kNoBits) {
                            EXPECT_EQ(outline.bitsFirst[c], ChartMasks::kNoBits);
                            continue;
                        }
                        const uint8_t *x = &all.bits[all.bitsFirst[c]], *y = &outline.bits[outline.bitsFirst[c]];
                        const size_t first = charts.chartFirstFace[c], faces = charts.chartFirstFace[c + 1] - first;
                        std::vector<glm::dvec2> corners(3 * faces);
                        for (size_t i = 0; i < 3 * faces; ++i)
                            corners[i] = (glm::dvec2(charts.wedgeUv[3 * first + i]) * a.scale + a.offset) * 0.5;
                        for (int row = 0; row < a.height; ++row)
                            for (int col = 0; col < a.width; ++col) {
                                const size_t k = size_t(row) * size_t(a.width) + size_t(col);
                                blocks += x[k];
                                ASSERT_FALSE(y[k] && !x[k]) << mesh.name << " chart " << c << ": a block more";
                                if (!x[k] || y[k])
                                    continue;
                                ++fewer;
                                const glm::dvec2 lo(col - margin, row - margin), hi(col + 1 + margin, row + 1 + margin);
                                for (size_t t = 0; t < faces; ++t)
                                    ASSERT_FALSE(squareMeetsTriangle(lo, hi, &corners[3 * t], 1e-9))
                                        << mesh.name << " chart " << c << " block " << col << ", " << row
                                        << " left out though triangle " << t << " meets it";
                            }
                        // The inside fill alone: the centres inside a triangle of the chart (one
                        // orientation, two densities: a test of every centre against every triangle).
                        if (turn > 0 || padding > 1 || (density != 1.9 && density != 8.0))
                            continue;
                        ChartOutline o;
                        if (faces < 16 || !chartOutline(charts, c, basis, a.scale, a.offset, 1e6, a.height, o))
                            continue;
                        ++outlined;
                        std::vector<uint8_t> inside(size_t(a.width) * size_t(a.height), 0);
                        fillInsideOutline(o, a.width, a.height, inside.data());
                        for (int row = 0; row < a.height; ++row)
                            for (int col = 0; col < a.width; ++col) {
                                const glm::dvec2 centre(col + 0.5, row + 0.5);
                                bool in = false, near = false;
                                for (size_t t = 0; t < faces; ++t) {
                                    const glm::dvec2 *q = &corners[3 * t];
                                    double least = INFINITY;
                                    for (int e = 0; e < 3; ++e) {
                                        const glm::dvec2 d = q[(e + 1) % 3] - q[e];
                                        least =
                                            std::min(least, doubleArea(q[e], q[(e + 1) % 3], centre) / glm::length(d));
                                    }
                                    in = in || least > 0;
                                    near = near || std::abs(least) < 1e-9;
                                }
                                if (near)
                                    continue;  // on an edge: either way
                                EXPECT_EQ(inside[size_t(row) * size_t(a.width) + size_t(col)] != 0, in)
                                    << mesh.name << " chart " << c << " centre " << col << ", " << row;
                            }
                    }
                }
        }
    EXPECT_GT(outlined, 50u) << "the outlines were exercised";
    // The corner blocks left out are rare (none on these families when written).
    EXPECT_LE(fewer, blocks / 1000) << fewer << " of " << blocks << " blocks";
    std::printf("%zu charts' insides checked; %zu of %zu blocks left out\n", outlined, fewer, blocks);
}

// The certificate that spares the outline and the mask's box their pass over every triangle: a
// chart it certifies at a scale has every triangle counter-clockwise with area under any offset
// within reach (checked triangle by triangle, as the rasteriser maps them), it certifies nearly
// every chart of ordinary meshes, and never a chart with a clockwise triangle, one without area,
// or triangles the rounding of the offset could flatten.
TEST(ChartOutline, CertifiedChartsTurnLeftUnderEveryOffset) {
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    size_t certified = 0, charts = 0;
    for (const TestMesh &base : families()) {
        const TestMesh mesh = turned(base, random);
        const AtlasCharts atlasCharts = computeCharts(mesh.view());
        const ChartOutlineBasis basis = chartOutlineBasis(atlasCharts);
        for (double scale : {1e-3, 0.37, 2.0, 8.0, 61.0, 900.0})
            for (size_t c = 0; c < atlasCharts.chartCount(); ++c) {
                if (atlasCharts.isDegenerate(c))
                    continue;
                const double reach = 3 + 40 * std::abs(unit(random));
                ++charts;
                if (!basis.certainlyTurnsLeft(c, scale, reach))
                    continue;
                ++certified;
                for (const glm::dvec2 offset : {glm::dvec2(reach, -reach), glm::dvec2(-reach, reach), glm::dvec2(0.0),
                                                glm::dvec2(unit(random), unit(random)) * reach})
                    for (uint32_t i = atlasCharts.chartFirstFace[c]; i < atlasCharts.chartFirstFace[c + 1]; ++i) {
                        glm::dvec2 p[3];
                        for (int k = 0; k < 3; ++k)
                            p[k] = (glm::dvec2(atlasCharts.wedgeUv[3 * i + uint32_t(k)]) * scale + offset) * 0.5;
                        ASSERT_GT(doubleArea(p[0], p[1], p[2]), 0) << mesh.name << " chart " << c << " at " << scale;
                    }
            }
    }
    EXPECT_GT(certified, charts * 9 / 10) << certified << " of " << charts << " charts certified";

    // A chart of two triangles; one made clockwise, or a sliver of relative area 1e-15.
    AtlasCharts two;
    two.chartFirstFace = {0, 2};
    two.chartFaces = {0, 1};
    two.faceChart = {0, 0};
    two.chartAxis = {glm::vec3(0, 0, 1)};
    two.chartSize = {glm::vec2(4, 4)};
    two.wedgeUv = {{0, 0}, {4, 0}, {4, 4}, {0, 0}, {4, 4}, {0, 4}};
    two.faceOpposite = {kNoOpposite, kNoOpposite, 5, kNoOpposite, kNoOpposite, 2};
    EXPECT_TRUE(chartOutlineBasis(two).certainlyTurnsLeft(0, 2.0, 5.0));
    std::swap(two.wedgeUv[4], two.wedgeUv[5]);  // the second triangle clockwise
    EXPECT_FALSE(chartOutlineBasis(two).certainlyTurnsLeft(0, 2.0, 5.0));
    two.wedgeUv = {{0, 0}, {4, 0}, {4, 4}, {0, 0}, {4, 4}, {2, 2.0000005f}};  // a float sliver: area 2e-6
    EXPECT_TRUE(chartOutlineBasis(two).certainlyTurnsLeft(0, 2.0, 5.0));
    // At a scale where the offset's rounding is the triangles' size, nothing is certain.
    EXPECT_FALSE(chartOutlineBasis(two).certainlyTurnsLeft(0, 1e-14, 5.0));
    two.wedgeUv[5] = {2, 2};  // no area
    EXPECT_FALSE(chartOutlineBasis(two).certainlyTurnsLeft(0, 2.0, 5.0));
    two.wedgeUv[5] = {0, NAN};
    EXPECT_FALSE(chartOutlineBasis(two).certainlyTurnsLeft(0, 2.0, 5.0));
}
