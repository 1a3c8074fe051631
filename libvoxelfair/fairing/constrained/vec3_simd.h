// Vector primitives of the constrained fairing, in SSE2 where the target has it and in plain GLM
// otherwise (base/simd_variant.h chooses).
//
// Contract: every SSE2 function gives bit for bit the result of the GLM expression it stands for
// (same operations in the same order: dot = (x x + y y) + z z, cross as glm::cross, normalize as
// v * (1 / sqrt(length2))).
// Why SSE by hand: glm's vec3 code compiles to stack round trips that stall, and four square
// roots and divisions in one instruction each are most of the cost of normalizing.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "base/simd_variant.h"
#include "mesh/vector_helpers.h"

#ifdef VOXELFAIR_SSE2
#include <emmintrin.h>
#endif

#if defined(__GNUC__)
#define VOXELFAIR_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define VOXELFAIR_NOINLINE __declspec(noinline)
#else
#define VOXELFAIR_NOINLINE
#endif

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

// The shared helpers (mesh/vector_helpers.h): the SSE2 kernels below reproduce normalizedOrZero.
using voxelfair::isFinite;
using voxelfair::normalizedOrZero;

#ifdef VOXELFAIR_SSE2
// glm::vec3 in a register (w = 0) and back, 12 bytes each way.
inline __m128 load3(const glm::vec3 &v) {
    const __m128 xy = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(&v.x)));  // unaligned
    return _mm_movelh_ps(xy, _mm_load_ss(&v.z));
}
inline void store3(glm::vec3 &v, __m128 x) {
    _mm_storel_epi64(reinterpret_cast<__m128i *>(&v.x), _mm_castps_si128(x));
    _mm_store_ss(&v.z, _mm_movehl_ps(x, x));
}
inline float dot3(__m128 a, __m128 b) {
    const __m128 p = _mm_mul_ps(a, b);
    return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, _mm_shuffle_ps(p, p, 1)), _mm_movehl_ps(p, p)));
}
inline __m128 cross3(__m128 a, __m128 b) {
    constexpr int yzx = _MM_SHUFFLE(3, 0, 2, 1), zxy = _MM_SHUFFLE(3, 1, 0, 2);
    return _mm_sub_ps(_mm_mul_ps(_mm_shuffle_ps(a, a, yzx), _mm_shuffle_ps(b, b, zxy)),
                      _mm_mul_ps(_mm_shuffle_ps(a, a, zxy), _mm_shuffle_ps(b, b, yzx)));
}

// normalizedOrZero of four vectors (lanes x, y, z; w = 0) at once.
inline void normalizeFour(__m128 &a, __m128 &b, __m128 &c, __m128 &d) {
    __m128 x = a, y = b, z = c, w = d;
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const __m128 length2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    const __m128 valid = _mm_and_ps(_mm_cmpgt_ps(length2, _mm_setzero_ps()),
                                    _mm_cmple_ps(length2, _mm_set1_ps(std::numeric_limits<float>::max())));
    const __m128 scale = _mm_and_ps(valid, _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(length2)));
    a = _mm_mul_ps(a, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(0, 0, 0, 0)));
    b = _mm_mul_ps(b, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(1, 1, 1, 1)));
    c = _mm_mul_ps(c, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(2, 2, 2, 2)));
    d = _mm_mul_ps(d, _mm_shuffle_ps(scale, scale, _MM_SHUFFLE(3, 3, 3, 3)));
}
#endif

// normalizedOrZero of `count` vectors in place, `stride` bytes apart.
inline void normalizeAll(glm::vec3 *vectors, size_t count, size_t stride = sizeof(glm::vec3)) {
    auto at = [&](size_t i) { return reinterpret_cast<glm::vec3 *>(reinterpret_cast<char *>(vectors) + i * stride); };
    size_t i = 0;
#ifdef VOXELFAIR_SSE2
    for (; i + 4 <= count; i += 4) {
        __m128 a = load3(*at(i)), b = load3(*at(i + 1)), c = load3(*at(i + 2)), d = load3(*at(i + 3));
        normalizeFour(a, b, c, d);
        store3(*at(i), a);
        store3(*at(i + 1), b);
        store3(*at(i + 2), c);
        store3(*at(i + 3), d);
    }
#endif
    for (; i < count; ++i)
        *at(i) = normalizedOrZero(*at(i));
}

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
