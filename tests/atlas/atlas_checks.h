// What every atlas must satisfy, whatever the mesh and options: shared by the atlas test files.
#pragma once

#include "atlas/atlas_measures.h"
#include "atlas/charts.h"
#include "atlas/packing.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <string>

namespace voxelfair::atlastest {

// The widest cone of the default charts: merged small charts' faces (chart_merge.h).
inline const float kMergeCone = ChartOptions().mergeCosine;

// UVs inside the texture, no texel or texel centre under two charts or faces, every face with UV
// area, stretch within the chart's cone.
inline void expectValidAtlas(const TestMesh &mesh, const AtlasCharts &charts, const AtlasLayout &layout, float cone) {
    SCOPED_TRACE(mesh.name + ", " + toString(layout.mode));
    ASSERT_EQ(layout.wedgeUv.size(), 3 * mesh.faceCount());
    for (const glm::vec2 &uv : layout.wedgeUv) {
        EXPECT_GE(uv.x, 0.0f);
        EXPECT_LE(uv.x, 1.0f);
        EXPECT_GE(uv.y, 0.0f);
        EXPECT_LE(uv.y, 1.0f);
    }
    const AtlasMeasures m = measureAtlas(mesh.view(), charts, layout);
    EXPECT_EQ(m.overlappingChartTexels, 0u);
    EXPECT_EQ(m.overlappingCentres, 0u);
    EXPECT_EQ(m.facesWithoutUvArea, 0u);
    EXPECT_LE(m.maxStretch, 1.0 + 1e-3);
    EXPECT_LE(m.maxInverseStretch, 1.0 / cone + 1e-3);
    EXPECT_GT(m.packingEfficiency, 0.0);
}

// Charts computed on another thread count: the same charts, UVs and counts as the reference.
inline void expectSameCharts(const AtlasCharts &charts, const AtlasCharts &reference, int threads) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    EXPECT_EQ(charts.chartFaces, reference.chartFaces);
    EXPECT_EQ(charts.chartFirstFace, reference.chartFirstFace);
    EXPECT_EQ(charts.faceChart, reference.faceChart);
    EXPECT_EQ(charts.wedgeUv, reference.wedgeUv);
    EXPECT_EQ(charts.chartAxis, reference.chartAxis);
    EXPECT_EQ(charts.chartSize, reference.chartSize);
    EXPECT_EQ(charts.mergedCharts, reference.mergedCharts);
    EXPECT_EQ(charts.splitCharts, reference.splitCharts);
    EXPECT_EQ(charts.foldedCharts, reference.foldedCharts);
}

}  // namespace voxelfair::atlastest
