// One texel's tangent-space solve; the contract is in texel_frames.h.
#include "maps/texel_frames.h"

#include "maps/texel_dilation.h"

#include <cmath>

namespace voxelfair {

namespace {
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

void writeTexelRow(const TargetFrame &frame, const TexelRow &row, uint8_t *states, uint32_t *rgba) {
    int i = 0;
    uint8_t *const s = states + row.x0;
    uint32_t *const c = rgba + row.x0;
#if VOXELFAIR_SSE2
    const FrameLanes lanes(frame);
    for (; i < row.size; i += 4) {
        const size_t k = size_t(i);
        const __m128 n[3] = {_mm_loadu_ps(&row.nx[k]), _mm_loadu_ps(&row.ny[k]), _mm_loadu_ps(&row.nz[k])};
        int solved = 0;
        alignas(16) uint32_t colour[4];
        _mm_store_si128(reinterpret_cast<__m128i *>(colour),
                        solveQuad(lanes, _mm_loadu_ps(&row.l1[k]), _mm_loadu_ps(&row.l2[k]), n, solved));
        uint32_t kept;
        std::memcpy(&kept, &row.keep[k], 4);
        if (kept == 0x01010101u && solved == 15 && i + 4 <= row.size) {
            std::memcpy(&c[k], colour, sizeof colour);
            std::memset(&s[k], kTexelPainted | kTexelFromSource, 4);
            continue;
        }
        for (int j = 0; j < 4 && i + j < row.size; ++j)
            if (row.keep[k + size_t(j)] != 0) {
                const bool ok = (solved >> j & 1) != 0;
                s[k + size_t(j)] = uint8_t(kTexelPainted | (ok ? kTexelFromSource : 0));
                if (ok)
                    c[k + size_t(j)] = colour[j];
            }
    }
#endif
    for (; i < row.size; ++i) {
        const size_t k = size_t(i);
        if (row.keep[k] == 0)
            continue;
        bool ok = false;
        const uint32_t colour = solveTexel(frame, row.l1[k], row.l2[k], glm::vec3(row.nx[k], row.ny[k], row.nz[k]), ok);
        s[k] = uint8_t(kTexelPainted | (ok ? kTexelFromSource : 0));
        if (ok)
            c[k] = colour;
    }
}

}  // namespace voxelfair
