// The cuts of sparse charts (chart_split.h) among other charts: a cut chart's pieces are written
// in its own range of chartFaces and the charts after it renumbered, on threads. Flat square
// rings (one chart each, cut) first in the mesh, so their charts come first, then a smoothed
// voxel sphere above the parallel threshold: every face's chart is the one whose range holds
// it, each ring is cut, and the charts are those of one thread on 2 and 5.
#include "atlas/charts.h"
#include "atlas_checks.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

using namespace voxelfair;
using namespace voxelfair::atlastest;

namespace {

// A square frame of bars one cell wide, n cells a side (under 1/8 of its box from n = 33 on), in the plane z = z0 at x = x0: two
// triangles a cell, counter-clockwise seen from +z.
void addRing(TestMesh &m, int n, float x0, float z0) {
    const uint32_t base = uint32_t(m.positions.size());
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.positions.push_back(glm::vec3(x0 + float(i), float(j), z0));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if (i == 0 || j == 0 || i == n - 1 || j == n - 1) {
                const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1) + 1, d = c - 1;
                m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
            }
}

}  // namespace

TEST(ChartSplit, CutChartsAmongOthersGiveTheSameChartsOnThreads) {
    TestMesh mesh;
    const int rings = 4;
    for (int r = 0; r < rings; ++r)
        addRing(mesh, 36 + 5 * r, -200.0f + 45.0f * float(r), -50.0f);
    const TestMesh sphere = smoothed(voxelSphere(16));
    const uint32_t base = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), sphere.positions.begin(), sphere.positions.end());
    for (const uint32_t v : sphere.triangles)
        mesh.triangles.push_back(base + v);
    ASSERT_GE(mesh.faceCount(), 4096u);
    ChartOptions one;
    one.threads = 1;
    const AtlasCharts reference = computeCharts(mesh.view(), one);
    EXPECT_EQ(reference.splitCharts, size_t(rings));
    ASSERT_GT(reference.chartCount(), size_t(4 * rings));
    for (size_t c = 0; c < reference.chartCount(); ++c)
        for (uint32_t i = reference.chartFirstFace[c]; i < reference.chartFirstFace[c + 1]; ++i)
            EXPECT_EQ(reference.faceChart[reference.chartFaces[i]], c) << "face at " << i;
    for (const int threads : {2, 5}) {
        ChartOptions options;
        options.threads = threads;
        expectSameCharts(computeCharts(mesh.view(), options), reference, threads);
    }
}
