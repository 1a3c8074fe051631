// The tangent-space texel of a target triangle: the unit solution c of c.x T + c.y B + c.z N = n,
// where N and T are the triangle's vertex normals and MikkTSpace tangents interpolated at the
// texel and normalised, B = sign * cross(N, T), and n the source normal found for it
// (normal_bake.h): the exact inverse of the glTF / Blender / MikkTSpace pixel shader.
// solveTexel solves one texel; solveQuad (SSE2) solves 4 texels at once, each lane repeating
// solveTexel's float operations in its order, so that both give the same colour bit for bit
// (texel_frames.cpp is compiled with -fno-math-errno: sqrt without errno). A TexelRow gathers the
// texels of one row of a triangle, solved 4 at a time and written by writeTexelRow.
#pragma once

#include "base/simd_variant.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/vec3.hpp>

#if VOXELFAIR_SSE2
#include <emmintrin.h>
#endif

namespace voxelfair {

// A target triangle's shading frame: corner normals and tangents (any non-zero length), the
// bitangent sign.
struct TargetFrame {
    float n[3][3], t[3][3];  // [corner][axis]
    float sign;
};

// The texel at barycentric weights (l1, l2; l0 = 1 - l1 - l2) with source normal n (zero: none):
// its colour R | G << 8 | B << 16 | 255 << 24, each (c + 1) / 2 * 255; `solved` false (the
// colour meaningless) for a texel without a frame (zero interpolated normal or tangent, singular
// basis, zero source normal).
uint32_t solveTexel(const TargetFrame &frame, float l1, float l2, const glm::vec3 &n, bool &solved);

#if VOXELFAIR_SSE2
// The frame with each coordinate in all 4 lanes (set once per target triangle).
struct FrameLanes {
    __m128 n[3][3], t[3][3], sign;
    explicit FrameLanes(const TargetFrame &f) {
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                n[k][a] = _mm_set1_ps(f.n[k][a]), t[k][a] = _mm_set1_ps(f.t[k][a]);
        sign = _mm_set1_ps(f.sign);
    }
};

// solveTexel on 4 lanes: the colours, and in `solved` bit k set when lane k is solved.
inline __m128i solveQuad(const FrameLanes &fr, __m128 l1, __m128 l2, const __m128 n[3], int &solved) {
    const __m128 one = _mm_set1_ps(1.0f), signBit = _mm_set1_ps(-0.0f);
    const __m128 l0 = _mm_sub_ps(_mm_sub_ps(one, l1), l2);
    __m128 N[3], T[3];
    for (int a = 0; a < 3; ++a) {
        N[a] =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, fr.n[0][a]), _mm_mul_ps(l1, fr.n[1][a])), _mm_mul_ps(l2, fr.n[2][a]));
        T[a] =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, fr.t[0][a]), _mm_mul_ps(l1, fr.t[1][a])), _mm_mul_ps(l2, fr.t[2][a]));
    }
    auto dot = [](const __m128 *u, const __m128 *v) {
        return _mm_add_ps(_mm_add_ps(_mm_mul_ps(u[0], v[0]), _mm_mul_ps(u[1], v[1])), _mm_mul_ps(u[2], v[2]));
    };
    // cross(u, v) component a: u[a+1] v[a+2] - u[a+2] v[a+1].
    auto cross = [](const __m128 *u, const __m128 *v, __m128 *out) {
        for (int a = 0; a < 3; ++a)
            out[a] = _mm_sub_ps(_mm_mul_ps(u[(a + 1) % 3], v[(a + 2) % 3]), _mm_mul_ps(u[(a + 2) % 3], v[(a + 1) % 3]));
    };
    const __m128 ni = _mm_div_ps(one, _mm_sqrt_ps(dot(N, N))), ti = _mm_div_ps(one, _mm_sqrt_ps(dot(T, T)));
    for (int a = 0; a < 3; ++a)
        N[a] = _mm_mul_ps(N[a], ni), T[a] = _mm_mul_ps(T[a], ti);
    __m128 r1[3], B[3], r0[3], r2[3];
    cross(N, T, r1);
    for (int a = 0; a < 3; ++a)
        B[a] = _mm_mul_ps(fr.sign, r1[a]);
    cross(B, N, r0);
    cross(T, B, r2);
    const __m128 x = dot(r0, n), y = dot(r1, n), z = dot(r2, n);
    const __m128 det = dot(T, r0),
                 length = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    solved = _mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(_mm_andnot_ps(signBit, det), _mm_set1_ps(1e-6f)),
                                        _mm_cmpgt_ps(length, _mm_setzero_ps())));
    const __m128 scale = _mm_div_ps(_mm_or_ps(_mm_and_ps(det, signBit), one), _mm_sqrt_ps(length));
    auto encode = [&](__m128 c) {  // texel_frames.cpp's encodeLane
        const __m128 v = _mm_add_ps(_mm_mul_ps(_mm_mul_ps(c, scale), _mm_set1_ps(127.5f)), _mm_set1_ps(128.0f));
        const __m128 low = _mm_and_ps(_mm_cmpgt_ps(v, _mm_setzero_ps()), v);
        return _mm_cvttps_epi32(_mm_min_ps(low, _mm_set1_ps(255.0f)));
    };
    return _mm_or_si128(_mm_or_si128(encode(x), _mm_slli_epi32(encode(y), 8)),
                        _mm_or_si128(_mm_slli_epi32(encode(z), 16), _mm_set1_epi32(int(0xFF000000u))));
}
#endif

// Texels [x0, x0 + size) of one image row: weights, source normal, and whether the texel is
// written (kept); one per thread, grown once.
struct TexelRow {
    std::vector<float> l1, l2, nx, ny, nz;  // 4 more than size: a quad's lanes past the end
    std::vector<uint8_t> keep;
    int x0 = 0, size = 0;
    void start(int first, int count) {
        if (l1.size() < size_t(count) + 4) {
            for (auto *v : {&l1, &l2, &nx, &ny, &nz})
                v->resize(size_t(count) + 4, 0.0f);
            keep.resize(size_t(count) + 4);
        }
        x0 = first, size = count;
        std::memset(keep.data(), 0, size_t(count));
    }
    void set(int x, float w1, float w2, const glm::vec3 &n) {
        const size_t i = size_t(x - x0);
        l1[i] = w1, l2[i] = w2, nx[i] = n.x, ny[i] = n.y, nz[i] = n.z, keep[i] = 1;
    }
#if VOXELFAIR_SSE2
    // Texels x .. x + 3, the first `kept` of them kept.
    void setQuad(int x, __m128 w1, __m128 w2, const __m128 n[3], int kept) {
        const size_t i = size_t(x - x0);
        _mm_storeu_ps(&l1[i], w1), _mm_storeu_ps(&l2[i], w2);
        _mm_storeu_ps(&nx[i], n[0]), _mm_storeu_ps(&ny[i], n[1]), _mm_storeu_ps(&nz[i], n[2]);
        std::memset(&keep[i], 1, size_t(kept));
    }
#endif
};

// A texel's state bit beside kTexelPainted (texel_dilation.h): its colour is the source's.
constexpr uint8_t kTexelFromSource = 2;

// The kept texels of `row` solved: states[x] = kTexelPainted, | kTexelFromSource where solved,
// rgba[x] = the colour where solved; the others left. states and rgba point at the row's x = 0.
void writeTexelRow(const TargetFrame &frame, const TexelRow &row, uint8_t *states, uint32_t *rgba);

}  // namespace voxelfair
