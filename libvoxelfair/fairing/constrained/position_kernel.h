// The vectorised kernel of step 3 (position_fit.cpp): one Gauss-Seidel update of four free
// vertices at once.
//
// Contract: for each lane j of a FitBlock with exactly kRegularValence neighbours (padded with
// the zero slot), with d the vertex's offset from its input position, n its normal, and the
// neighbours' (n_u . d_u, d_u) read at the byte offsets `neighbours`:
//     along = base + sum n_u . d_u + n . sum d_u - sumS . d,
//     d    <- clamp(d + along * stepScale * n, -half, half),   alongNormal <- n . d.
// This is the projected update of Sun et al. ("Fast and effective feature-preserving mesh
// denoising", IEEE TVCG 13(5), 2007) restricted to the vertex's own cell (Gibson, "Constrained
// elastic surface nets", MICCAI 1998); see position_fit.cpp for the least squares it solves.
// The four lanes must be independent (no lane a neighbour of another): the sweep's waves
// (sweep_layout.cpp) make them so, and then the result equals four updates one after another.
// Why in registers across the four: a few instructions per vertex where one at a time would need
// horizontal sums and shuffles (benchmarks/fairing_benchmark measures the difference).
#pragma once

#include "fairing/constrained/vec3_simd.h"

#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

// Neighbours of a regular free vertex as the sweeps read them (voxel surfaces have 3 to 6).
constexpr uint32_t kRegularValence = 6;

// Step 3's state per vertex, one 16-byte block: n . d and the offset d from the input position
// (n . d is 0 for vertices that are not free).
struct alignas(16) Offset {
    float alongNormal;
    glm::vec3 d;
};

// Step 3's fit for one pass of four free vertices (a block of slots), lane by lane.
struct alignas(16) FitBlock {
    float stepScale[4];         // 2 / sum |s|^2
    float nx[4], ny[4], nz[4];  // vertex normal
    float base[4];              // sum of s . (input_u - input_v)
    float sx[4], sy[4], sz[4];  // sum of s

    glm::vec3 n(int lane) const { return {nx[lane], ny[lane], nz[lane]}; }
    glm::vec3 sumS(int lane) const { return {sx[lane], sy[lane], sz[lane]}; }
};

// n . d of the four slots `own` of a block into along[0..3] (glm::dot's sums, in SSE four at once).
inline void alongNormalOfBlock(const FitBlock &f, const Offset *own, float *along) {
#ifdef VOXELFAIR_SSE2
    __m128 a = _mm_load_ps(&own[0].alongNormal), dx = _mm_load_ps(&own[1].alongNormal),
           dy = _mm_load_ps(&own[2].alongNormal), dz = _mm_load_ps(&own[3].alongNormal);
    _MM_TRANSPOSE4_PS(a, dx, dy, dz);
    _mm_storeu_ps(along, _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_load_ps(f.nx), dx), _mm_mul_ps(_mm_load_ps(f.ny), dy)),
                                    _mm_mul_ps(_mm_load_ps(f.nz), dz)));
#else
    for (int lane = 0; lane < 4; ++lane)
        along[lane] = glm::dot(f.n(lane), own[lane].d);
#endif
}

// One Gauss-Seidel step of a free vertex, given `along`.
inline void moveFreeVertex(const FitBlock &f, int lane, float along, float half, Offset &o) {
    const glm::vec3 n = f.n(lane);
    o.d = glm::clamp(o.d + (along * f.stepScale[lane]) * n, -half, half);
    o.alongNormal = glm::dot(n, o.d);
}

// The update of the contract for the four vertices `own` of a block; `neighbours` holds
// 4 * kRegularValence byte offsets into `offsets` (saving an instruction per neighbour).
#ifdef VOXELFAIR_SSE2
inline void moveFreeBlock(const FitBlock &f, const uint32_t *neighbours, Offset *offsets, Offset *own, float half) {
    static_assert(kRegularValence == 6, "unrolled below");
    const char *const bytes = reinterpret_cast<const char *>(offsets);
    auto load = [&](uint32_t offset) { return _mm_load_ps(reinterpret_cast<const float *>(bytes + offset)); };
    __m128 sum[4];  // (sum n_u . d_u, sum d_u) per vertex
    for (int j = 0; j < 4; ++j, neighbours += kRegularValence)
        sum[j] = _mm_add_ps(_mm_add_ps(_mm_add_ps(load(neighbours[0]), load(neighbours[1])),
                                       _mm_add_ps(load(neighbours[2]), load(neighbours[3]))),
                            _mm_add_ps(load(neighbours[4]), load(neighbours[5])));
    _MM_TRANSPOSE4_PS(sum[0], sum[1], sum[2], sum[3]);
    __m128 a = _mm_load_ps(&own[0].alongNormal), dx = _mm_load_ps(&own[1].alongNormal),
           dy = _mm_load_ps(&own[2].alongNormal), dz = _mm_load_ps(&own[3].alongNormal);
    _MM_TRANSPOSE4_PS(a, dx, dy, dz);
    const __m128 nx = _mm_load_ps(f.nx), ny = _mm_load_ps(f.ny), nz = _mm_load_ps(f.nz);
    const __m128 along = _mm_sub_ps(
        _mm_add_ps(_mm_add_ps(sum[0], _mm_load_ps(f.base)),
                   _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, sum[1]), _mm_mul_ps(ny, sum[2])), _mm_mul_ps(nz, sum[3]))),
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_load_ps(f.sx), dx), _mm_mul_ps(_mm_load_ps(f.sy), dy)),
                   _mm_mul_ps(_mm_load_ps(f.sz), dz)));
    const __m128 step = _mm_mul_ps(along, _mm_load_ps(f.stepScale)), lo = _mm_set1_ps(-half), hi = _mm_set1_ps(half);
    dx = _mm_min_ps(_mm_max_ps(_mm_add_ps(dx, _mm_mul_ps(step, nx)), lo), hi);
    dy = _mm_min_ps(_mm_max_ps(_mm_add_ps(dy, _mm_mul_ps(step, ny)), lo), hi);
    dz = _mm_min_ps(_mm_max_ps(_mm_add_ps(dz, _mm_mul_ps(step, nz)), lo), hi);
    a = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)), _mm_mul_ps(nz, dz));
    _MM_TRANSPOSE4_PS(a, dx, dy, dz);
    _mm_store_ps(&own[0].alongNormal, a);
    _mm_store_ps(&own[1].alongNormal, dx);
    _mm_store_ps(&own[2].alongNormal, dy);
    _mm_store_ps(&own[3].alongNormal, dz);
}
#else
inline void moveFreeBlock(const FitBlock &f, const uint32_t *neighbours, Offset *offsets, Offset *own, float half) {
    float along[4];
    for (int j = 0; j < 4; ++j, neighbours += kRegularValence) {
        glm::vec3 sumD(0.0f);
        float sumAlong = 0.0f;
        for (uint32_t i = 0; i < kRegularValence; ++i) {
            const Offset &o = offsets[neighbours[i] / sizeof(Offset)];
            sumD += o.d;
            sumAlong += o.alongNormal;
        }
        along[j] = sumAlong + f.base[j] + glm::dot(f.n(j), sumD) - glm::dot(f.sumS(j), own[j].d);
    }
    for (int j = 0; j < 4; ++j)
        moveFreeVertex(f, j, along[j], half, own[j]);
}
#endif

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
