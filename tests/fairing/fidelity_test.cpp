// Section 4.3's claim, measured: one pass of the modified-Lanczos fairing brings the voxel
// surface much closer to the true surface it was sampled from.
#include "smoothers/smoothing_comparison.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

using namespace voxelfair;

namespace {

class FairingFidelity : public ::testing::TestWithParam<shapes::Shape> {};

std::string testName(const ::testing::TestParamInfo<shapes::Shape> &info) {
    std::string name;
    for (char c : info.param.name)
        if (std::isalnum(static_cast<unsigned char>(c)))
            name += c;
    return name;
}

}  // namespace

TEST_P(FairingFidelity, OnePassAtLeastHalvesTheVoxelError) {
    const shapes::Shape &shape = GetParam();
    const std::vector<comparison::Row> rows = comparison::compare(shape);
    for (const comparison::Row &row : rows)
        std::printf("%-16s %-16s rms %.4f  max %.4f  bias %+.4f  volume %+.2f%%\n", row.shape.c_str(),
                    row.method.c_str(), row.error.rms, row.error.max, row.error.bias, row.error.volumeChangePercent);
    ASSERT_GE(rows.size(), 2u);
    const shapes::SurfaceError &raw = rows[0].error, &paper = rows[1].error;
    ASSERT_TRUE(std::isfinite(paper.rms) && std::isfinite(paper.max));

    const bool isBox = shape.name == "box";
    if (isBox) {
        // Lattice-aligned: the raw surface is exact; only edges and corners get rounded.
        EXPECT_LT(raw.rms, 1e-6);
        EXPECT_LT(paper.rms, 0.12);
        return;
    }
    // Sanity of the measurement: a staircase around a surface at random offsets is off by a
    // uniform [-1/2, 1/2] voxel, RMS 1/sqrt(12) = 0.289.
    EXPECT_NEAR(raw.rms, 0.289, 0.04);
    EXPECT_LT(raw.max, 0.9);
    if (shape.name.rfind("sphere", 0) == 0 || shape.name.rfind("torus", 0) == 0)
        EXPECT_LE(paper.rms, 0.5 * raw.rms);
    else
        EXPECT_LT(paper.rms, raw.rms);  // thin cylinders: better, not necessarily halved
}

INSTANTIATE_TEST_SUITE_P(Shapes, FairingFidelity, ::testing::ValuesIn(comparison::comparisonShapes()), testName);
