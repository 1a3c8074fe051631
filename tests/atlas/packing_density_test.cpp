// The density search of the packer (packing.h): where it starts and how a larger model's fill is
// aimed, on families of smoothed voxel shapes.
#include "atlas/atlas_measures.h"
#include "atlas/charts.h"
#include "atlas/packing.h"
#include "atlas_checks.h"
#include "shapes/atlas_test_meshes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

using namespace voxelfair;
using namespace voxelfair::atlastest;

// PackOptions::startDensity: the separation rounds restart the density search next to the last
// answer. Wherever it starts, the search ends at a fitting layout near the density the search
// from the area bound finds (both stop within 0.5% of a miss), and a start just above the answer
// costs fewer packings (here 51 against 95 in all). Fixed sizes and densities lowered to fit the largest texture, on a
// family of smoothed voxel shapes.
TEST(Packing, AStartDensityNearTheAnswerSavesPackings) {
    const std::vector<TestMesh> shapes = {smoothed(voxelSphere(9)), smoothed(voxelTorus(10, 4)),
                                          smoothed(voxelBlob(8, 3)), smoothed(voxelBlob(7, 11)),
                                          smoothed(voxelBox(9, 5, 3))};
    size_t fromScratch = 0, nearStart = 0;
    for (const TestMesh &shape : shapes) {
        const AtlasCharts charts = computeCharts(shape.view());
        PackOptions fixed, reduced;
        fixed.textureSize = 256;
        reduced.texelsPerUnit = 64.0f;
        reduced.maxTextureSize = 256;
        for (const PackOptions &base : {fixed, reduced}) {
            const AtlasLayout scratch = packCharts(charts, base);
            ASSERT_EQ(scratch.densityReduced, base.textureSize == 0) << shape.name;
            for (double factor : {0.6, 0.98, 1.002, 1.05, 1.6}) {
                PackOptions started = base;
                started.startDensity = scratch.texelsPerUnit * factor;
                const AtlasLayout layout = packCharts(charts, started);
                SCOPED_TRACE(shape.name + " start x" + std::to_string(factor));
                EXPECT_EQ(measureAtlas(shape.view(), charts, layout).overlappingChartTexels, 0u);
                // 0.2% on the round shapes; the box's six charts fit at some densities and not at
                // slightly lower ones (a packer is not monotone in the density), 2.4% there.
                EXPECT_NEAR(layout.texelsPerUnit, scratch.texelsPerUnit, 0.03 * scratch.texelsPerUnit);
                for (const glm::vec2 &uv : layout.wedgeUv)
                    ASSERT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
                if (factor == 1.002)
                    fromScratch += scratch.packAttempts, nearStart += layout.packAttempts;
            }
        }
    }
    EXPECT_LT(nearStart, fromScratch);
}

// A larger model's masks that fill little of the first texture shape are packed first where their
// room fills most of it (packCharts, kFirstFillShare): on a fit, nearly full, that is the only
// packing (the masks at the asked density are only measured). Every model is "larger" here
// (cheapFillFaces 0). The texture is
// never larger than the smallest that holds the asked density, which stays a minimum.
TEST(Packing, ALargerModelIsFirstPackedWhereItFillsTheTexture) {
    const std::vector<TestMesh> shapes = {smoothed(voxelSphere(9)), smoothed(voxelTorus(10, 4)),
                                          smoothed(voxelBlob(8, 3)), smoothed(voxelBox(9, 5, 3))};
    size_t once = 0, cases = 0;
    for (const TestMesh &shape : shapes) {
        const AtlasCharts charts = computeCharts(shape.view());
        for (float density : {2.0f, 3.3f, 5.0f, 8.0f}) {
            PackOptions options;
            options.texelsPerUnit = density;
            options.cheapFillFaces = 0;
            options.leastChartShare = 0;  // small textures do not step up here
            PackOptions asked = options;
            asked.fillTexture = false;
            const AtlasLayout least = packCharts(charts, asked), layout = packCharts(charts, options);
            SCOPED_TRACE(shape.name + " at " + std::to_string(density));
            expectValidAtlas(shape, charts, layout, kMergeCone);
            EXPECT_GE(layout.texelsPerUnit, density);
            EXPECT_LE(int64_t(layout.width) * layout.height, int64_t(least.width) * least.height);
            EXPECT_GE(measureAtlas(shape.view(), charts, layout).packingEfficiency,
                      measureAtlas(shape.view(), charts, least).packingEfficiency);
            ++cases;
            once += layout.packAttempts == 1 && layout.texelsPerUnit >= density * 1.04;
        }
    }
    EXPECT_GE(once, 2u) << "packed once, at the aim, in " << once << " of " << cases;
}
