// The merges of small charts (chart_merge.h) on threads: with two or more, a second thread builds
// the large charts' face grids while the merges run, and the merges build or wait for the ones
// they need first. The charts must be those of one thread on larger meshes of several shapes,
// with small charts of up to 8 faces (the default) and of up to 100 (then charts with grids move
// too, and charts grown past the grid size by merges get theirs late).
#include "atlas/charts.h"
#include "atlas_checks.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::atlastest;

TEST(ChartMerge, MergesOnThreadsGiveTheSameCharts) {
    const std::vector<TestMesh> shapes = {smoothed(voxelSphere(16)), smoothed(voxelTorus(18, 7)),
                                          smoothed(voxelBlob(16, 5)), smoothed(voxelBlob(18, 9), 5)};
    for (const TestMesh &shape : shapes)
        for (const size_t mergeFaces : {size_t(8), size_t(100)}) {
            SCOPED_TRACE(shape.name + " mergeFaces " + std::to_string(mergeFaces));
            ASSERT_GE(shape.faceCount(), 4096u);  // above the parallel threshold
            ChartOptions one;
            one.threads = 1;
            one.mergeFaces = mergeFaces;
            const AtlasCharts reference = computeCharts(shape.view(), one);
            EXPECT_GT(reference.mergedCharts, 0u);
            for (const int threads : {2, 5}) {
                ChartOptions options = one;
                options.threads = threads;
                expectSameCharts(computeCharts(shape.view(), options), reference, threads);
            }
        }
}
