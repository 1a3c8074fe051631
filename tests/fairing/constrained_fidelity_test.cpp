// The second fairing mode's goal (constrained_fairing.h), measured on voxelized analytic shapes
// of several sizes and sub-voxel offsets (comparison::fidelityShapes): with its defaults, RMS
// distance to the true surface at most 0.095 voxel on spheres (radius 6-24) and tori, 0.17 on
// capped cylinders along the axes (radius 3-6), 0.03 on axis-aligned boxes (which in fact stay
// exact), volume within 1% for spheres of radius 12 and up and for the tori, and below the paper's
// pass and MeshLab's Taubin Smooth on every rounded shape. The bounds were 0.07 and 0.14 before
// the drift removal (constrained_fairing.h, step 5): it keeps flat faces and fillets from
// inflating (tests/fairing/family_fidelity_test.cpp) and costs these shapes up to 0.02 (worst:
// a torus of tube radius 4 around the x axis, 0.091; spheres centred on a voxel centre, 0.080).
#include "smoothers/smoothing_comparison.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

using namespace voxelfair;

namespace voxelfair::comparison {
// Names the parameter in test listings (GoogleTest would dump its bytes).
void PrintTo(const FamilyShape &shape, std::ostream *os) { *os << shape.shape.name; }
}  // namespace voxelfair::comparison

namespace {

class FairingConstrainedFidelity : public ::testing::TestWithParam<comparison::FamilyShape> {};

std::string testName(const ::testing::TestParamInfo<comparison::FamilyShape> &info) {
    std::string name;
    for (char c : info.param.shape.name)
        if (std::isalnum(static_cast<unsigned char>(c)))
            name += c;
    return name;
}

const comparison::Row *find(const std::vector<comparison::Row> &rows, const std::string &prefix) {
    for (const comparison::Row &row : rows)
        if (row.method.rfind(prefix, 0) == 0)
            return &row;
    return nullptr;
}

}  // namespace

TEST_P(FairingConstrainedFidelity, MeetsTheGoalAndBeatsTheOtherSmoothers) {
    const comparison::FamilyShape &param = GetParam();
    comparison::Options options;
    options.samples = 20000;       // RMS to about 0.5% (the tool uses 200000)
    options.otherMeshLab = false;  // (tools/compare_smoothing has them)
    const std::vector<comparison::Row> rows = comparison::compare(param.shape, options);
    for (const comparison::Row &row : rows)
        std::printf("%-16s %-16s rms %.4f  max %.4f  bias %+.4f  volume %+.2f%%\n", row.shape.c_str(),
                    row.method.c_str(), row.error.rms, row.error.max, row.error.bias, row.error.volumeChangePercent);
    const comparison::Row *paper = find(rows, "paper"), *taubin = find(rows, "vcg Taubin"),
                          *ours = find(rows, comparison::kConstrainedMethod);
    ASSERT_TRUE(paper && ours);
    const shapes::SurfaceError &e = ours->error;
    ASSERT_TRUE(std::isfinite(e.rms) && std::isfinite(e.max));

    if (param.family == "box") {
        // Flat faces stay flat and edges sharp: the raw surface is exact and nothing moves.
        EXPECT_LE(e.rms, 0.03);
        EXPECT_LT(e.max, 1e-4);
        return;
    }
    const double goal = param.family == "cylinder" ? 0.17 : 0.095;
    EXPECT_LE(e.rms, goal);
    if ((param.family == "sphere" && param.size >= 12.0) || param.family == "torus") {
        EXPECT_LE(std::fabs(e.volumeChangePercent), 1.0);
    }
    EXPECT_LT(e.rms, paper->error.rms);
    if (taubin) {
        EXPECT_LT(e.rms, taubin->error.rms);
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, FairingConstrainedFidelity, ::testing::ValuesIn(comparison::fidelityShapes()),
                         testName);
