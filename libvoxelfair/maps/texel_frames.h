// The tangent-space texel of a target triangle: the unit solution c of c.x T + c.y B + c.z N = n,
// where N and T are the triangle's vertex normals and MikkTSpace tangents interpolated at the
// texel and normalised, B = sign * cross(N, T), and n the source normal found for it
// (normal_bake.h): the exact inverse of the glTF / Blender / MikkTSpace pixel shader.
// solveTexel solves one texel; solveQuad (SSE2) solves 4 texels at once, each lane repeating
// solveTexel's float operations in its order, so that both give the same colour bit for bit
// (texel_frames.cpp is compiled with -fno-math-errno: sqrt without errno). A TexelBatch gathers the
// texels of a triangle, solved 4 (SSE2) or 8 (AVX2, chosen at run time) at a time and written
// by writeTexelBatch.
#pragma once

#include "base/simd_variant.h"

#include <cstddef>
#include <cstdint>
#include <algorithm>
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

// The texels of one target triangle, gathered row by row (texels [x0, x0 + size) of each row,
// rows one after another): weights, source normal, and whether the texel is written (kept); one
// per thread, grown once. Solved all at once (writeTexelBatch): full vectors whatever the rows'
// lengths.
struct TexelBatch {
    static constexpr int kPad = 8;          // lanes past the end a vector may touch
    std::vector<float> l1, l2, nx, ny, nz;  // size + kPad
    std::vector<uint8_t> keep;              // size + kPad
    std::vector<uint32_t> colour;           // the solve's output, size + kPad
    std::vector<uint8_t> solved;            // 1 where solved, size + kPad
    struct Row {
        uint32_t state, image;  // offsets of the row's x = 0 in the states and the image
        int x0, begin, size;    // texels x0 .. x0 + size - 1 at begin .. begin + size - 1
    };
    std::vector<Row> rows;
    int size = 0;
    std::ptrdiff_t base = 0;  // the current row's x = 0 in the arrays (begin - x0)
    void clear() { rows.clear(), size = 0; }
    void startRow(uint32_t stateRow, uint32_t imageRow, int first, int count) {
        const size_t need = size_t(size) + size_t(count) + kPad;
        if (l1.size() < need) {
            const size_t grown = std::max(need, 2 * l1.size());
            for (auto *v : {&l1, &l2, &nx, &ny, &nz})
                v->resize(grown, 0.0f);
            keep.resize(grown), colour.resize(grown), solved.resize(grown);
        }
        rows.push_back({stateRow, imageRow, first, size, count});
        std::memset(&keep[size_t(size)], 0, size_t(count));
        base = std::ptrdiff_t(size) - first;
        size += count;
    }
    void set(int x, float w1, float w2, const glm::vec3 &n) {
        const size_t i = size_t(base + x);
        l1[i] = w1, l2[i] = w2, nx[i] = n.x, ny[i] = n.y, nz[i] = n.z, keep[i] = 1;
    }
#if VOXELFAIR_SSE2
    // Texels x .. x + 3 of the current row, the first `kept` (0 to 4) of them kept, the others
    // not (they are set again later, or lie past the row's end: the next row starts there).
    void setQuad(int x, __m128 w1, __m128 w2, const __m128 n[3], int kept) {
        const size_t i = size_t(base + x);
        _mm_storeu_ps(&l1[i], w1), _mm_storeu_ps(&l2[i], w2);
        _mm_storeu_ps(&nx[i], n[0]), _mm_storeu_ps(&ny[i], n[1]), _mm_storeu_ps(&nz[i], n[2]);
        const uint32_t lanes = uint32_t((uint64_t(1) << (8 * kept)) - 1) & 0x01010101u;
        std::memcpy(&keep[i], &lanes, 4);
    }
#endif
};
// A texel's state bit beside kTexelPainted (texel_dilation.h): its colour is the source's.
constexpr uint8_t kTexelFromSource = 2;

// The kept texels of `batch` solved (8 lanes at once where the CPU has AVX2, else 4 with SSE2,
// else one by one: the same colours bit for bit) and written: states[x] = kTexelPainted,
// | kTexelFromSource where solved, rgba[x] = the colour where solved; the others left (each row
// at its offsets in states and rgba).
void writeTexelBatch(const TargetFrame &frame, TexelBatch &batch, uint8_t *states, uint32_t *rgba);

}  // namespace voxelfair
