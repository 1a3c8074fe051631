// Source faces by their place in the atlas, for the normal bake (normal_bake.h): where a
// target texel's search for its source point starts. The source shares the target's atlas
// (decimation with texture keeps the UVs), so the source face whose UV triangle holds a texel's
// centre is the natural start:
//   SortedSource     the source with its faces renumbered by UV cell (faces near in the atlas
//                    near in memory);
//   fillFacesUnder   per band of rows, the source face under each texel centre (a scanline fill);
//   UvFaceGrid       the fallback where no face is under a texel: the face holding a UV point,
//                    else the one with the nearest UV centroid in its cell;
//   faceBands        target faces by the bands of rows they touch.
// UVs are scaled to texel space: u * width, v * height (rows from v = 0 up).
#pragma once

#include "atlas/texel_raster.h"
#include "base/simd_variant.h"
#include "maps/normal_bake.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/vec2.hpp>

#if VOXELFAIR_SSE2
#include <emmintrin.h>
#endif

namespace voxelfair {

inline void loadUv(const NormalBakeMesh &m, size_t f, int width, int height, glm::dvec2 q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = glm::dvec2(m.wedgeUv[3 * f + size_t(k)]) * glm::dvec2(width, height);
}

// The source with its faces renumbered by the atlas cell (kSortCell texels square) of their UV
// centroid, cells row by row (a counting sort): faces near in the atlas are near in memory, and
// the source faces under a target face lie in a few runs the walk can fetch ahead.
struct SortedSource {
    static constexpr int kSortCell = 16;
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> wedgeUv;
    int cellsX = 0, cellsY = 0;
    std::vector<uint32_t> cellStart;   // the faces of cell c: [cellStart[c], cellStart[c + 1])
    std::vector<uint32_t> sortedFace;  // the source's face f is face sortedFace[f] here
    NormalBakeMesh mesh;

    SortedSource(const NormalBakeMesh &source, int width, int height);
    uint32_t cell(double x, double y) const {
        const int cx = std::isfinite(x) ? std::clamp(int(x / kSortCell), 0, cellsX - 1) : 0;
        const int cy = std::isfinite(y) ? std::clamp(int(y / kSortCell), 0, cellsY - 1) : 0;
        return uint32_t(cy) * uint32_t(cellsX) + uint32_t(cx);
    }
};

// Source faces by the texel-space boxes of their UV triangles, in cells of 16 x 16 texels: where
// a texel's walk starts when no source face is under it (a few thousand asks). The faces of a
// cell are found when asked, not listed up front: a face's box meets the cells within kReach of
// its centroid's cell (the sorted source's bucket), or it is one of the few wide faces kept apart.
class UvFaceGrid {
public:
    UvFaceGrid(const SortedSource &sorted, int width, int height);
    // The source face (in the sorted source) whose UV triangle holds texel-space point p, else
    // the one whose UV centroid is nearest among those whose box meets p's cell, the first in
    // face order of either; UINT32_MAX when none meets the cell.
    uint32_t find(glm::dvec2 p) const;

private:
    static constexpr int kCell = SortedSource::kSortCell;
    static constexpr int kReach = 1;
    const SortedSource &sorted_;
    int width_, height_, cellsX_, cellsY_;
    std::vector<uint16_t> box_;   // per face: its box's first and last cells, x0, x1, y0, y1
    std::vector<uint32_t> wide_;  // faces whose box reaches beyond kReach of their bucket
};

// Target faces by the bands of rows their UV triangles may touch (conservatively), in face order.
struct FaceBands {
    std::vector<uint32_t> start, faces;
};

FaceBands faceBands(const NormalBakeMesh &mesh, int width, int height, int bandRows);

// Calls span(y, xl, xr) for the rows y in [r0, r1) with texel centres (x + 0.5, y + 0.5) in the
// UV triangle uv (scaled to texels), x in [xl, xr] within the image: a plain scanline fill in
// floats, for the walk's starting faces (where neighbouring triangles share an edge, a centre
// on it may be given to either; both are right starts).
template <class Span>
void underSpans(const glm::vec2 *uv, int width, int height, int r0, int r1, Span &&span) {
    const glm::vec2 q[3] = {uv[0] * glm::vec2(float(width), float(height)),
                            uv[1] * glm::vec2(float(width), float(height)),
                            uv[2] * glm::vec2(float(width), float(height))};
    const float area = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (!(area != 0.0f) || !std::isfinite(area))
        return;
    const float lo = std::min({q[0].y, q[1].y, q[2].y}), hi = std::max({q[0].y, q[1].y, q[2].y});
    // Bounds beyond the rows or the image are clamped before their ceil or floor (the range or
    // span is empty, or its end clamped, either way), so they are within the int range.
    const float rowLo = float(r0 - 1), rowHi = float(r1);
    const int y0 = std::max(r0, ceilToInt(std::clamp(lo - 0.5f, rowLo, rowHi))),
              y1 = std::min(r1 - 1, floorToInt(std::clamp(hi - 0.5f, rowLo, rowHi)));
    if (y0 > y1)
        return;  // no row of [r0, r1) (faces are banded conservatively)
    // Edge a -> b bounds the inside where sign(area) * cross(b - a, c - a) >= 0: for a row, x
    // >= or <= its crossing a.x + (cy - a.y) ex / ey (left or right bound by the sign of
    // -sign(area) ey); a horizontal edge bounds the rows instead (cy on its inner side).
    // A triangle of nonzero area has one or two left bounds, one or two right bounds and at most
    // one horizontal edge (its edges' ey sum to 0). Each side's bounds are taken in edge order, a
    // single one twice (max(max(-1, c), c) = max(-1, c), NaN included): per row no branch on the
    // edges, the same bounds as testing each edge's side in turn.
    float ax[3], ay[3], inverse[3];
    int left[2], right[2], leftCount = 0, rightCount = 0, horizontal = -1;
    float rowSign = 0.0f;
    const float s = area > 0.0f ? 1.0f : -1.0f;
    for (int k = 0; k < 3; ++k) {
        const glm::vec2 a = q[k], b = q[(k + 1) % 3];
        const float ex = b.x - a.x, ey = b.y - a.y;
        ax[k] = a.x, ay[k] = a.y;
        inverse[k] = ey != 0.0f ? ex / ey : 0.0f;
        if (-s * ey > 0.0f)
            left[leftCount++] = k;
        else if (-s * ey < 0.0f)
            right[rightCount++] = k;
        else
            horizontal = k, rowSign = s * ex;  // inside where s ex (cy - a.y) >= 0
    }
    if (leftCount == 0 || rightCount == 0)
        return;  // unreached (the area test leaves finite triangles of nonzero area, which have a
                 // bound on each side: the sign of a float difference is exact); guards left[0]
    if (leftCount == 1)
        left[1] = left[0];
    if (rightCount == 1)
        right[1] = right[0];
    // The bounds' edges in locals (kept in registers through the rows).
    const float lx0 = ax[left[0]], ly0 = ay[left[0]], li0 = inverse[left[0]];
    const float lx1 = ax[left[1]], ly1 = ay[left[1]], li1 = inverse[left[1]];
    const float rx0 = ax[right[0]], ry0 = ay[right[0]], ri0 = inverse[right[0]];
    const float rx1 = ax[right[1]], ry1 = ay[right[1]], ri1 = inverse[right[1]];
    const float horizontalY = horizontal >= 0 ? ay[horizontal] : 0.0f;
    int y = y0;
#if VOXELFAIR_SSE2
    // 4 rows at once, each lane the float operations of the row loop below in its order (the
    // max/min operand orders keep std::max/std::min's answers: xl and xr are never NaN here),
    // the spans given in row order.
    {
        auto all = [](float v) { return _mm_set1_ps(v); };
        const __m128 half = all(0.5f), w = all(float(width)), minusOne = all(-1.0f);
        for (; y <= y1; y += 4) {
            const __m128 cy =
                _mm_add_ps(_mm_cvtepi32_ps(_mm_add_epi32(_mm_set1_epi32(y), _mm_setr_epi32(0, 1, 2, 3))), half);
            const __m128 l0 = _mm_add_ps(all(lx0), _mm_mul_ps(_mm_sub_ps(cy, all(ly0)), all(li0)));
            const __m128 l1 = _mm_add_ps(all(lx1), _mm_mul_ps(_mm_sub_ps(cy, all(ly1)), all(li1)));
            const __m128 r0v = _mm_add_ps(all(rx0), _mm_mul_ps(_mm_sub_ps(cy, all(ry0)), all(ri0)));
            const __m128 r1v = _mm_add_ps(all(rx1), _mm_mul_ps(_mm_sub_ps(cy, all(ry1)), all(ri1)));
            const __m128 xl = _mm_max_ps(l1, _mm_max_ps(l0, minusOne));  // max(max(-1, l0), l1)
            const __m128 xr = _mm_min_ps(r1v, _mm_min_ps(r0v, w));       // min(min(w, r0), r1)
            const __m128 from = _mm_sub_ps(_mm_min_ps(w, xl), half), to = _mm_sub_ps(_mm_max_ps(xr, minusOne), half);
            const __m128i fromInt = _mm_cvttps_epi32(from), toInt = _mm_cvttps_epi32(to);
            // ceil: + 1 where the truncation is below; floor: - 1 where it is above.
            const __m128i a4 = _mm_sub_epi32(fromInt, _mm_castps_si128(_mm_cmplt_ps(_mm_cvtepi32_ps(fromInt), from)));
            const __m128i b4 = _mm_add_epi32(toInt, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(toInt), to)));
            const int skip = horizontal >= 0
                                 ? _mm_movemask_ps(_mm_cmplt_ps(
                                       _mm_mul_ps(all(rowSign), _mm_sub_ps(cy, all(horizontalY))), _mm_setzero_ps()))
                                 : 0;
            alignas(16) int as[4], bs[4];
            _mm_store_si128(reinterpret_cast<__m128i *>(as), a4);
            _mm_store_si128(reinterpret_cast<__m128i *>(bs), b4);
            for (int k = 0; k < std::min(4, y1 - y + 1); ++k) {
                const int a = std::max(0, as[k]), b = std::min(width - 1, bs[k]);
                if ((skip >> k & 1) == 0 && a <= b)
                    span(y + k, a, b);
            }
        }
    }
#endif
    for (; y <= y1; ++y) {
        const float cy = float(y) + 0.5f;
        if (horizontal >= 0 && rowSign * (cy - horizontalY) < 0.0f)
            continue;
        const float xl = std::max(std::max(-1.0f, lx0 + (cy - ly0) * li0), lx1 + (cy - ly1) * li1);
        const float xr = std::min(std::min(float(width), rx0 + (cy - ry0) * ri0), rx1 + (cy - ry1) * ri1);
        // Texels whose centre x + 0.5 lies in [xl, xr].
        const int a = std::max(0, ceilToInt(std::min(xl, float(width)) - 0.5f)),
                  b = std::min(width - 1, floorToInt(std::max(xr, -1.0f) - 0.5f));
        if (a <= b)
            span(y, a, b);
    }
}

// The source face under each texel centre of rows [r0, r1): rows[(y - r0) * width + x] = face
// for the centres inside face `face`'s UV triangle (later faces overwrite earlier ones).
inline void fillFacesUnder(const NormalBakeMesh &mesh, uint32_t face, int width, int height, int r0, int r1,
                           uint32_t *rows) {
    const uint32_t four[4] = {face, face, face, face};
    underSpans(mesh.wedgeUv + 3 * size_t(face), width, height, r0, r1, [&](int y, int xl, int xr) {
        // Spans are a few texels: 4 at a time, the last 4 overlapping, else one by one.
        uint32_t *const to = &rows[size_t(y - r0) * size_t(width) + size_t(xl)];
        const int n = xr - xl + 1;
        if (n >= 4) {
            for (int i = 0; i + 4 < n; i += 4)
                std::memcpy(to + i, four, sizeof four);
            std::memcpy(to + n - 4, four, sizeof four);
        } else {
            for (int i = 0; i < n; ++i)
                to[i] = face;
        }
    });
}

}  // namespace voxelfair
