#include "fairing/lanczos_kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace voxelfair;

// doc/method.md §4: F as a function of the raw mean u, with d = (4/3) u.
TEST(FairingLanczosKernel, MatchesTheAuthorsTable) {
    const struct {
        double u, f;
    } table[] = {{0.05, 0.008}, {0.1, 0.032},  {0.25, 0.190}, {1.0 / 3.0, 0.320}, {0.5, 0.619},
                 {0.6, 0.793},  {0.75, 1.000}, {0.9, 1.118},  {1.0, 1.146}};
    for (const auto &row : table) {
        EXPECT_NEAR(lanczosDisplacementReference(4.0 / 3.0 * row.u), row.f, 5e-4) << "u = " << row.u;
        EXPECT_NEAR(lanczosDisplacement(float(4.0 / 3.0 * row.u)), row.f, 5e-4) << "u = " << row.u;
        EXPECT_NEAR(lanczosDisplacement(float(-4.0 / 3.0 * row.u)), -row.f, 5e-4) << "u = " << row.u;
    }
    EXPECT_EQ(lanczosDisplacement(0.0f), 0.0f);
    EXPECT_EQ(lanczosDisplacement(1.0f), 1.0f);  // L3(1) = 0: sin(pi) vanishes exactly in the triple-angle form
}

TEST(FairingLanczosKernel, OneSineFormAgreesWithReference) {
    // Dense sweep over the polynomial range (|d| <= 3/2) and beyond it (libm fallback).
    double worst = 0.0;
    for (int i = -300000; i <= 300000; ++i) {
        const double d = i * 1e-5;
        worst =
            std::max(worst, std::fabs(double(lanczosDisplacement(float(d))) - lanczosDisplacementReference(float(d))));
    }
    EXPECT_LT(worst, 1e-6);
}

TEST(FairingLanczosKernel, SmallFrequenciesBarelyMove) {
    // 1 - L3(d) ~ (10 pi^2 / 54) d^2 near 0: an adaptive low-pass, not a uniform shrink.
    const double c = 10.0 * M_PI * M_PI / 54.0;
    EXPECT_NEAR(lanczosDisplacementReference(1e-3) / 1e-6, c, 1e-4);
    EXPECT_NEAR(lanczosDisplacement(0.01f), c * 1e-4, 2e-6);
}
