// What the voxels alone cannot tell: two different shapes with the same voxels, so no smoother of
// the voxels (ours, the paper's, MeshLab's, VTK's) can be near both. Issue 15 asks, shape by shape
// "at any orientation and sub-voxel offset", for an RMS of at most 0.08 voxels on cylinders and
// 0.03 on axis-aligned boxes; each test below shows a pair of shapes of one of those families where
// every output misses that goal on at least one of the two, whatever the method.
//
// Why: any surface's samples s have |d(s, A)| + |d(s, B)| >= |sdf_A(s) - sdf_B(s)|, so by
// Minkowski's inequality RMS_A + RMS_B >= RMS(sdf_A - sdf_B) over the samples, and one of the two
// is at least half of that; the difference is large wherever the two truths part. Voxels are solid
// where their centre is inside (shapes::voxelize).
#include "smoothers/smoothing_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

using namespace voxelfair;

namespace {

// Both shapes give the same voxels; every method of the comparison gives one mesh for both, whose
// RMS distances to the two truths must sum to more than `sumAtLeast` (and the larger exceed
// `maxAtLeast`), each well over twice the goal.
void expectSameVoxelsApart(const shapes::Shape &a, const shapes::Shape &b, double sumAtLeast, double maxAtLeast) {
    const BoundarySurface sa = extractBoundarySurface(shapes::voxelize(a));
    const BoundarySurface sb = extractBoundarySurface(shapes::voxelize(b));
    ASSERT_GT(sa.quadCount(), 0u);
    ASSERT_EQ(sa.positions, sb.positions);
    ASSERT_EQ(sa.quads, sb.quads);

    comparison::Options options;
    options.samples = 50000;
    const std::vector<comparison::Row> rowsA = comparison::compare(a, options);
    const std::vector<comparison::Row> rowsB = comparison::compare(b, options);
    ASSERT_EQ(rowsA.size(), rowsB.size());
    ASSERT_GE(rowsA.size(), 3u);  // raw, the paper's pass, the constrained mode at least
    for (size_t i = 0; i < rowsA.size(); ++i) {
        const comparison::Row &r = rowsA[i], &s = rowsB[i];
        ASSERT_EQ(r.method, s.method);
        EXPECT_DOUBLE_EQ(r.error.volume, s.error.volume) << r.method << ": not the same mesh";
        std::printf("%-20s RMS against the first: %.3f, against the second: %.3f\n", r.method.c_str(), r.error.rms,
                    s.error.rms);
        EXPECT_GT(r.error.rms + s.error.rms, sumAtLeast) << r.method;
        EXPECT_GT(std::max(r.error.rms, s.error.rms), maxAtLeast) << r.method;
    }
}

// Capped cylinders around the same lattice line (x = y = 8, z from 3 to 15), radius 2.95 and
// 3.50. A voxel centre's squared distance to that axis is (m + 1/2)^2 + (n + 1/2)^2 =
// 2 (T_m + T_n) + 1/2, T the triangular numbers 0, 1, 3, 6, 10, ...; no sum of two of them is 5,
// so no centre lies at 8.5 < rho^2 < 12.5, between radius 2.916 and 3.536: every radius in between
// gives the same voxels. On the sides (four fifths of the surface) the truths are 0.55 apart.
// Issue 15's goal on cylinders: 0.08.
TEST(InformationLimit, CylindersOfRadius2_95And3_5OnALatticeAxisHaveTheSameVoxels) {
    const glm::dvec3 bottom(8.0, 8.0, 3.0), top(8.0, 8.0, 15.0);
    expectSameVoxelsApart(shapes::cappedCylinder(bottom, top, 2.95), shapes::cappedCylinder(bottom, top, 3.50), 0.40,
                          0.20);
}

// Axis-aligned 10 x 8 x 6 boxes, x from 1.6 to 11.6 and from 2.4 to 12.4: both hold the voxel
// centres x = 2.5 ... 11.5, so both are the same voxels, and the same as the box on the lattice
// from 2 to 12. Their x faces (a quarter of the surface) are 0.8 apart. Issue 15's goal on
// axis-aligned boxes: 0.03 (met where the faces lie on the lattice: exact).
TEST(InformationLimit, AxisAlignedBoxesOffsetByFourFifthsOfAVoxelHaveTheSameVoxels) {
    const glm::dvec3 half(5.0, 4.0, 3.0);
    expectSameVoxelsApart(shapes::box({6.6, 6.0, 5.0}, half), shapes::box({7.4, 6.0, 5.0}, half), 0.30, 0.15);
}

}  // namespace
