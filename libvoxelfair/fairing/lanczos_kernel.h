// The displacement function of section 4.3, eq. 9: a frequency d (eq. 8, lambda included) is
// mapped to a displacement in voxels
//     F(d) = sign(d) * (1 - L3(d)),   L_a(x) = a sin(pi x) sin(pi x / a) / (pi x)^2,  L_a(0) = 1.
// Smooth regions barely move (F ~ 1.83 d^2 near 0); the voxel staircase (|d| near 1) moves by
// about one voxel: F(1) = 1 exactly, F(4/3) = 1.146 is the largest move at lambda 4/3.
#pragma once

#include <cmath>

namespace voxelfair {

// Eq. 9 as written, two sines in double precision: the reference the fast form is tested against.
inline double lanczosDisplacementReference(double d) {
    if (d == 0.0)
        return 0.0;
    const double pi = 3.14159265358979323846;
    const double x = pi * std::fabs(d);
    const double window = 3.0 * std::sin(x) * std::sin(x / 3.0) / (x * x);
    return std::copysign(1.0 - window, d);
}

// sin(t) for |t| <= pi/2: odd Taylor polynomial up to t^13 (truncation error < 7e-10 there).
inline float sinTaylor13(float t) {
    const float t2 = t * t;
    float p = 1.0f / 6227020800.0f;
    p = p * t2 - 1.0f / 39916800.0f;
    p = p * t2 + 1.0f / 362880.0f;
    p = p * t2 - 1.0f / 5040.0f;
    p = p * t2 + 1.0f / 120.0f;
    p = p * t2 - 1.0f / 6.0f;
    return t + t * t2 * p;
}

// Eq. 9 with one sine: with s = sin(pi d / 3), sin(pi d) = s (3 - 4 s^2) (triple angle), so
// L3(d) = 3 s^2 (3 - 4 s^2) / (pi d)^2. For |d| <= 3/2 (every lambda up to 3/2) s comes from the
// polynomial above, without a libm call; agrees with the reference within 1e-6.
inline float lanczosDisplacement(float d) {
    if (d == 0.0f)
        return 0.0f;
    const float pi = 3.14159265f;
    const float x = pi * std::fabs(d);
    const float t = x * (1.0f / 3.0f);
    const float s = t <= 0.5f * pi ? sinTaylor13(t) : std::sin(t);
    const float s2 = s * s;
    const float window = 3.0f * s2 * (3.0f - 4.0f * s2) / (x * x);
    return std::copysign(1.0f - window, d);
}

}  // namespace voxelfair
