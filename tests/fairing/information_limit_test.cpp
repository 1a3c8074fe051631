// What the voxels alone cannot tell: two different cylinders with the same voxels, so no smoother
// of the voxels (ours, the paper's, MeshLab's, VTK's) can be near both. Issue 15 asks for an RMS
// of at most 0.08 voxels on "cylinders at any angle and sub-voxel offset", shape by shape; this
// test shows a pair of shapes of that family where every output misses that goal on at least one
// of the two, whatever the method.
//
// The pair: capped cylinders around the same lattice line (x = y = 8, z from 3 to 15), radius 2.95
// and 3.50. Voxels are solid where their centre is inside (shapes::voxelize). A centre's squared
// distance to that axis is (m + 1/2)^2 + (n + 1/2)^2 = 2 (T_m + T_n) + 1/2, T the triangular
// numbers 0, 1, 3, 6, 10, ...; no sum of two of them is 5, so no centre lies at 8.5 < rho^2 < 12.5,
// i.e. between radius 2.916 and 3.536: every radius in between gives the same voxels.
//
// Any surface's samples s then have |d(s, A)| + |d(s, B)| >= |sdf_A(s) - sdf_B(s)|, which is 0.55
// wherever both distances are the sides' (most of the surface: the caps are a fifth of it), so by
// Minkowski's inequality RMS_A + RMS_B >= RMS(sdf_A - sdf_B) over the samples, and one of the two
// is at least half of that. Measured below on every method of the comparison.
#include "smoothers/smoothing_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

using namespace voxelfair;

namespace {

const glm::dvec3 kBottom(8.0, 8.0, 3.0), kTop(8.0, 8.0, 15.0);

TEST(InformationLimit, CylindersOfRadius2_95And3_5OnALatticeAxisHaveTheSameVoxels) {
    const shapes::Shape thin = shapes::cappedCylinder(kBottom, kTop, 2.95);
    const shapes::Shape thick = shapes::cappedCylinder(kBottom, kTop, 3.50);
    const BoundarySurface a = extractBoundarySurface(shapes::voxelize(thin));
    const BoundarySurface b = extractBoundarySurface(shapes::voxelize(thick));
    ASSERT_GT(a.quadCount(), 0u);
    ASSERT_EQ(a.positions, b.positions);
    ASSERT_EQ(a.quads, b.quads);

    // The same voxels, so every method returns the same mesh for both; measured against each.
    comparison::Options options;
    options.samples = 50000;
    const std::vector<comparison::Row> rowsThin = comparison::compare(thin, options);
    const std::vector<comparison::Row> rowsThick = comparison::compare(thick, options);
    ASSERT_EQ(rowsThin.size(), rowsThick.size());
    ASSERT_GE(rowsThin.size(), 3u);  // raw, the paper's pass, the constrained mode at least
    for (size_t i = 0; i < rowsThin.size(); ++i) {
        const comparison::Row &r = rowsThin[i], &s = rowsThick[i];
        ASSERT_EQ(r.method, s.method);
        EXPECT_DOUBLE_EQ(r.error.volume, s.error.volume) << r.method << ": not the same mesh";
        std::printf("%-20s RMS against radius 2.95: %.3f, against 3.50: %.3f\n", r.method.c_str(), r.error.rms,
                    s.error.rms);
        // Most samples lie on the sides, where the two truths are 0.55 apart: the two RMS sum to
        // well over twice issue 15's 0.08, so the goal fails on one of the two shapes.
        EXPECT_GT(r.error.rms + s.error.rms, 0.40) << r.method;
        EXPECT_GT(std::max(r.error.rms, s.error.rms), 0.20) << r.method;
    }
}

}  // namespace
