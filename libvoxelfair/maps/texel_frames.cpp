// One texel's tangent-space solve; the contract is in texel_frames.h.
#include "maps/texel_frames.h"

#include "maps/texel_dilation.h"

#include <cmath>

namespace voxelfair {

namespace {
// Bit j of an 8-bit mask as byte j (0 or 1) of a little-endian word: a solve's `solved` lanes
// stored at once.
struct SpreadBits {
    uint64_t word[256];
    constexpr SpreadBits() : word() {
        for (int mask = 0; mask < 256; ++mask)
            for (int j = 0; j < 8; ++j)
                word[mask] |= uint64_t(mask >> j & 1) << (8 * j);
    }
};
constexpr SpreadBits kSpreadBits;
inline void storeSolved(uint8_t *solved, int mask, size_t lanes) {
    const uint64_t word = kSpreadBits.word[mask];
    std::memcpy(solved, &word, lanes);
}

// (c + 1) / 2 in 0..255 (NaN -> 0), as solveQuad's encode does it.
int encodeLane(float c) {
    const float v = c * 127.5f + 128.0f, low = v > 0.0f ? v : 0.0f;
    return int(low < 255.0f ? low : 255.0f);
}

}  // namespace

uint32_t solveTexel(const TargetFrame &fr, float l1, float l2, const glm::vec3 &source, bool &solved) {
    const float l0 = 1.0f - l1 - l2;
    float N[3], T[3];
    for (int a = 0; a < 3; ++a) {
        N[a] = l0 * fr.n[0][a] + l1 * fr.n[1][a] + l2 * fr.n[2][a];
        T[a] = l0 * fr.t[0][a] + l1 * fr.t[1][a] + l2 * fr.t[2][a];
    }
    const float ni = 1.0f / std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]),
                ti = 1.0f / std::sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
    for (int a = 0; a < 3; ++a)
        N[a] *= ni, T[a] *= ti;
    // B = sign cross(N, T); rows of the inverse of the column matrix [T B N]: cross products
    // over its determinant.
    const float B[3] = {fr.sign * (N[1] * T[2] - N[2] * T[1]), fr.sign * (N[2] * T[0] - N[0] * T[2]),
                        fr.sign * (N[0] * T[1] - N[1] * T[0])};
    const float r0[3] = {B[1] * N[2] - B[2] * N[1], B[2] * N[0] - B[0] * N[2], B[0] * N[1] - B[1] * N[0]};
    const float r1[3] = {N[1] * T[2] - N[2] * T[1], N[2] * T[0] - N[0] * T[2], N[0] * T[1] - N[1] * T[0]};
    const float r2[3] = {T[1] * B[2] - T[2] * B[1], T[2] * B[0] - T[0] * B[2], T[0] * B[1] - T[1] * B[0]};
    const float n[3] = {source.x, source.y, source.z};
    const float x = r0[0] * n[0] + r0[1] * n[1] + r0[2] * n[2], y = r1[0] * n[0] + r1[1] * n[1] + r1[2] * n[2],
                z = r2[0] * n[0] + r2[1] * n[1] + r2[2] * n[2];
    const float det = T[0] * r0[0] + T[1] * r0[1] + T[2] * r0[2], length = x * x + y * y + z * z;
    // Without a frame NaNs or zeros reach here, and fail these tests.
    solved = (std::fabs(det) > 1e-6f) & (length > 0.0f);
    const float scale = std::copysign(1.0f, det) / std::sqrt(length);
    return uint32_t(encodeLane(x * scale)) | uint32_t(encodeLane(y * scale)) << 8 |
           uint32_t(encodeLane(z * scale)) << 16 | 0xFF000000u;
}

#if VOXELFAIR_SSE2 && (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#define VOXELFAIR_AVX2_DISPATCH 1
#include <immintrin.h>
namespace {

// solveQuad on 8 lanes (AVX2 when the CPU has it, chosen at run time): the same operations in
// the same order, without fused multiply-adds (the target is "avx2" alone), so every lane gives
// solveQuad's and solveTexel's colour bit for bit.
#define VOXELFAIR_AVX2 __attribute__((target("avx2")))
VOXELFAIR_AVX2 inline __m256 dot8(const __m256 *u, const __m256 *v) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(u[0], v[0]), _mm256_mul_ps(u[1], v[1])),
                         _mm256_mul_ps(u[2], v[2]));
}
// cross(u, v) component a: u[a+1] v[a+2] - u[a+2] v[a+1].
VOXELFAIR_AVX2 inline void cross8(const __m256 *u, const __m256 *v, __m256 *out) {
    for (int a = 0; a < 3; ++a)
        out[a] =
            _mm256_sub_ps(_mm256_mul_ps(u[(a + 1) % 3], v[(a + 2) % 3]), _mm256_mul_ps(u[(a + 2) % 3], v[(a + 1) % 3]));
}
// encodeLane of c * scale on 8 lanes.
VOXELFAIR_AVX2 inline __m256i encode8(__m256 c, __m256 scale) {
    const __m256 v =
        _mm256_add_ps(_mm256_mul_ps(_mm256_mul_ps(c, scale), _mm256_set1_ps(127.5f)), _mm256_set1_ps(128.0f));
    const __m256 low = _mm256_and_ps(_mm256_cmp_ps(v, _mm256_setzero_ps(), _CMP_GT_OQ), v);
    return _mm256_cvttps_epi32(_mm256_min_ps(low, _mm256_set1_ps(255.0f)));
}
VOXELFAIR_AVX2 void solveOcts(const TargetFrame &fr, TexelBatch &b) {
    const __m256 one = _mm256_set1_ps(1.0f), signBit = _mm256_set1_ps(-0.0f);
    __m256 fn[3][3], ft[3][3];
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a)
            fn[k][a] = _mm256_set1_ps(fr.n[k][a]), ft[k][a] = _mm256_set1_ps(fr.t[k][a]);
    const __m256 sign = _mm256_set1_ps(fr.sign);
    for (int i = 0; i < b.size; i += 8) {
        const size_t k = size_t(i);
        const __m256 l1 = _mm256_loadu_ps(&b.l1[k]), l2 = _mm256_loadu_ps(&b.l2[k]);
        const __m256 n[3] = {_mm256_loadu_ps(&b.nx[k]), _mm256_loadu_ps(&b.ny[k]), _mm256_loadu_ps(&b.nz[k])};
        const __m256 l0 = _mm256_sub_ps(_mm256_sub_ps(one, l1), l2);
        __m256 N[3], T[3];
        for (int a = 0; a < 3; ++a) {
            N[a] = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(l0, fn[0][a]), _mm256_mul_ps(l1, fn[1][a])),
                                 _mm256_mul_ps(l2, fn[2][a]));
            T[a] = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(l0, ft[0][a]), _mm256_mul_ps(l1, ft[1][a])),
                                 _mm256_mul_ps(l2, ft[2][a]));
        }
        const __m256 ni = _mm256_div_ps(one, _mm256_sqrt_ps(dot8(N, N))),
                     ti = _mm256_div_ps(one, _mm256_sqrt_ps(dot8(T, T)));
        for (int a = 0; a < 3; ++a)
            N[a] = _mm256_mul_ps(N[a], ni), T[a] = _mm256_mul_ps(T[a], ti);
        __m256 r1[3], B[3], r0[3], r2[3];
        cross8(N, T, r1);
        for (int a = 0; a < 3; ++a)
            B[a] = _mm256_mul_ps(sign, r1[a]);
        cross8(B, N, r0);
        cross8(T, B, r2);
        const __m256 x = dot8(r0, n), y = dot8(r1, n), z = dot8(r2, n);
        const __m256 det = dot8(T, r0), length = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(x, x), _mm256_mul_ps(y, y)),
                                                               _mm256_mul_ps(z, z));
        const int ok = _mm256_movemask_ps(
            _mm256_and_ps(_mm256_cmp_ps(_mm256_andnot_ps(signBit, det), _mm256_set1_ps(1e-6f), _CMP_GT_OQ),
                          _mm256_cmp_ps(length, _mm256_setzero_ps(), _CMP_GT_OQ)));
        const __m256 scale = _mm256_div_ps(_mm256_or_ps(_mm256_and_ps(det, signBit), one), _mm256_sqrt_ps(length));
        const __m256i colour = _mm256_or_si256(
            _mm256_or_si256(encode8(x, scale), _mm256_slli_epi32(encode8(y, scale), 8)),
            _mm256_or_si256(_mm256_slli_epi32(encode8(z, scale), 16), _mm256_set1_epi32(int(0xFF000000u))));
        _mm256_storeu_si256(reinterpret_cast<__m256i *>(&b.colour[k]), colour);
        storeSolved(&b.solved[k], ok, 8);
    }
}
#undef VOXELFAIR_AVX2

const bool kHasAvx2 = __builtin_cpu_supports("avx2");

}  // namespace
#endif

void writeTexelBatch(const TargetFrame &frame, TexelBatch &b, uint8_t *states, uint32_t *rgba) {
    // The solve: every lane (unkept ones too, their answers unused), full vectors over the batch.
#if VOXELFAIR_SSE2
#if VOXELFAIR_AVX2_DISPATCH
    if (kHasAvx2) {
        solveOcts(frame, b);
    } else
#endif
    {
        const FrameLanes lanes(frame);
        for (int i = 0; i < b.size; i += 4) {
            const size_t k = size_t(i);
            const __m128 n[3] = {_mm_loadu_ps(&b.nx[k]), _mm_loadu_ps(&b.ny[k]), _mm_loadu_ps(&b.nz[k])};
            int ok = 0;
            _mm_storeu_si128(reinterpret_cast<__m128i *>(&b.colour[k]),
                             solveQuad(lanes, _mm_loadu_ps(&b.l1[k]), _mm_loadu_ps(&b.l2[k]), n, ok));
            storeSolved(&b.solved[k], ok, 4);
        }
    }
#else
    for (int i = 0; i < b.size; ++i) {
        const size_t k = size_t(i);
        bool ok = false;
        if (b.keep[k] != 0)
            b.colour[k] = solveTexel(frame, b.l1[k], b.l2[k], glm::vec3(b.nx[k], b.ny[k], b.nz[k]), ok);
        b.solved[k] = ok ? 1 : 0;
    }
#endif
    // The writes, row by row: 4 texels at once where all are kept and solved.
    for (const TexelBatch::Row &row : b.rows) {
        uint8_t *const s = states + row.state + row.x0;
        uint32_t *const c = rgba + row.image + row.x0;
        const uint8_t *const keep = &b.keep[size_t(row.begin)], *const solved = &b.solved[size_t(row.begin)];
        const uint32_t *const colour = &b.colour[size_t(row.begin)];
        int i = 0;
        for (; i + 4 <= row.size; i += 4) {
            uint32_t kept, ok;
            std::memcpy(&kept, keep + i, 4);
            std::memcpy(&ok, solved + i, 4);
            if ((kept & ok) == 0x01010101u) {
                std::memcpy(&c[i], colour + i, 16);
                std::memset(&s[i], kTexelPainted | kTexelFromSource, 4);
                continue;
            }
            for (int j = i; j < i + 4; ++j)
                if (keep[j] != 0) {
                    s[j] = uint8_t(kTexelPainted | (solved[j] != 0 ? kTexelFromSource : 0));
                    if (solved[j] != 0)
                        c[j] = colour[j];
                }
        }
        for (; i < row.size; ++i)
            if (keep[i] != 0) {
                s[i] = uint8_t(kTexelPainted | (solved[i] != 0 ? kTexelFromSource : 0));
                if (solved[i] != 0)
                    c[i] = colour[i];
            }
    }
}

}  // namespace voxelfair
