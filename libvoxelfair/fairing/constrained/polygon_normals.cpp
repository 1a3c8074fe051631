// Polygon normals of the constrained fairing: the input's (with which vertices and polygons are
// usable, and the voxel size) and, for later passes, the faired surface's.
//
// Contract (findNormals): kind[v] = Skipped for non-finite vertices, Free otherwise; a polygon is
// live when it has 3+ corners, finite vertices and non-zero area, and normal[p] is its unit
// normal from its vector area (Newell's method; for a quad half the cross product of its
// diagonals), zero when it is not live; normal[P] = normal[P + 1] = 0 stand for "no polygon".
// The voxel size is options.voxelSize when given; else, when every polygon edge has one length,
// that length (what detectVoxelSize would find, without its sampling and sorting); else
// detectVoxelSize. False, with report.status = NothingToDo, when there is no usable size.
// findFairedNormals recomputes the live polygons' normals at input + offset.
#include "fairing/constrained/fairing_state.h"
#include "fairing/voxel_size.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {
constexpr size_t kGrain = 4096;  // vertices or polygons a thread takes at a time (a multiple of 4)
}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE bool findNormals(FairingState<kQuads> &s) {
    const size_t V = s.V, P = s.P;
    VertexKind *const kind = s.kind;
    const glm::vec3 *const input = s.input;
    // (Vertex ranges, then polygon ranges, split between the threads: each writes its own
    // entries; the count, and the edge lengths' agreement below, do not depend on the order.)
    std::atomic<size_t> skippedCount{0};
    s.threads.forRanges(V, kGrain, [&skippedCount, kind, input](size_t firstVertex, size_t lastVertex) {
        size_t skippedHere = 0;
        for (size_t v = firstVertex; v < lastVertex; ++v) {
#ifdef VOXELFAIR_SSE2
            const __m128 x = load3(input[v]);  // x - x is 0 when finite, NaN otherwise
            const bool finite = (_mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(x, x), _mm_setzero_ps())) & 7) == 7;
#else
            const bool finite = isFinite(input[v]);
#endif
            kind[v] = finite ? VertexKind::Free : VertexKind::Skipped;
            skippedHere += !finite;
        }
        skippedCount += skippedHere;
    });
    const size_t skipped = skippedCount.load();
    s.report.skippedVertices = skipped;
    s.normal[s.P] = s.normal[s.P + 1] = glm::vec3(0.0f);
    const uint32_t *const indices = s.indices;
    glm::vec3 *const normal = s.normal;
    uint8_t *const live = s.live;
    const Polygons<kQuads> k = s.k;
    auto at = [input, indices](uint32_t i) { return input[indices[i]]; };
    // Each range's edges: all of one length (oneLength), and that length (-1: none seen).
    const size_t ranges = (P + kGrain - 1) / kGrain;
    std::vector<std::pair<uint8_t, float>> rangeLengths(ranges, {uint8_t(1), -1.0f});
    s.threads.run(ranges, [&rangeLengths, k, kind, indices, normal, live, at, skipped, P](size_t range) {
        float edgeLength2 = -1.0f;  // -1: none seen yet
        bool oneLength = true;
        const size_t firstPolygon = range * kGrain, lastPolygon = std::min(P, firstPolygon + kGrain);
        for (size_t p = firstPolygon; p < lastPolygon; ++p) {
            const uint32_t first = k.first(p), last = k.last(p);
            bool finite = last - first >= 3;
            if (skipped > 0)
                for (uint32_t i = first; finite && i < last; ++i)
                    finite = kind[indices[i]] != VertexKind::Skipped;
            normal[p] = glm::vec3(0.0f);
            live[p] = 0;
            if (!finite) {
                oneLength = oneLength && last - first < 2;
                continue;
            }
#ifdef VOXELFAIR_SSE2
            if constexpr (kQuads) {
                const __m128 x0 = load3(at(first)), x1 = load3(at(first + 1)), x2 = load3(at(first + 2)),
                             x3 = load3(at(first + 3));
                if (oneLength) {
                    const __m128 e0 = _mm_sub_ps(x1, x0), e1 = _mm_sub_ps(x2, x1), e2 = _mm_sub_ps(x3, x2),
                                 e3 = _mm_sub_ps(x0, x3);
                    const float length2 = dot3(e0, e0);
                    oneLength = (edgeLength2 == length2 || edgeLength2 < 0.0f) && dot3(e1, e1) == length2 &&
                                dot3(e2, e2) == length2 && dot3(e3, e3) == length2;
                    edgeLength2 = length2;
                }
                const __m128 area = cross3(_mm_sub_ps(x2, x0), _mm_sub_ps(x3, x1));
                store3(normal[p], area);  // normalized below, to zero exactly when this fails:
                const float length2 = dot3(area, area);
                live[p] = length2 > 0.0f && length2 <= std::numeric_limits<float>::max();
                continue;
            }
#endif
            if (oneLength) {
                for (uint32_t i = first; i < last; ++i) {
                    const glm::vec3 e = at(i + 1 < last ? i + 1 : first) - at(i);
                    const float length2 = glm::dot(e, e);
                    oneLength = oneLength && (edgeLength2 == length2 || edgeLength2 < 0.0f);
                    edgeLength2 = length2;
                }
            }
            normal[p] = areaNormal(at, first, last);
            live[p] = 1;
        }
        normalizeAll(normal + firstPolygon, lastPolygon - firstPolygon);  // no-op on the normalized ones
#ifdef VOXELFAIR_SSE2
        if constexpr (!kQuads)
#endif
            for (size_t p = firstPolygon; p < lastPolygon; ++p)
                live[p] = live[p] && normal[p] != glm::vec3(0.0f);
        rangeLengths[range] = {uint8_t(oneLength), edgeLength2};
    });
    // One length over all the ranges: each range's, and all the same.
    float edgeLength2 = -1.0f;
    bool oneLength = true;
    for (const auto &[one, length2] : rangeLengths) {
        if (!one)
            oneLength = false;
        else if (length2 >= 0.0f) {
            oneLength = oneLength && (edgeLength2 == length2 || edgeLength2 < 0.0f);
            edgeLength2 = length2;
        }
    }
    if (s.options.voxelSize > 0.0f)
        s.report.voxelSize = s.options.voxelSize;
    else if (oneLength && edgeLength2 > 0.0f && std::isfinite(std::sqrt(edgeLength2)))
        s.report.voxelSize = std::sqrt(edgeLength2);
    else
        s.report.voxelSize = detectVoxelSize(PolygonMesh{s.input, s.V, s.offsets, s.indices, s.P});
    if (!(s.report.voxelSize > 0.0f)) {
        s.report.status = FairingStatus::NothingToDo;
        s.report.message = "no polygon edge of non-zero finite length to take the voxel size from";
        return false;
    }
    s.half = s.options.cellHalfWidth * s.report.voxelSize;
    return true;
}

template <bool kQuads>
VOXELFAIR_NOINLINE void findFairedNormals(FairingState<kQuads> &s) {
    const size_t P = s.P;
    const uint8_t *const live = s.live;
    glm::vec3 *const normal = s.normal;
#ifdef VOXELFAIR_SSE2
    if constexpr (kQuads) {
        const glm::vec3 *const input = s.input;
        const Offset *const offset = s.offset;
        const uint32_t *const indices = s.indices, *const rank = s.rank;
        auto at = [&](uint32_t i) {
            const uint32_t v = indices[i];
            return _mm_add_ps(load3(input[v]), load3(offset[rank[v]].d));
        };
        // Polygon by polygon, in ranges split between the threads (stage_threads.h).
        s.threads.forRanges(P, 4096, [&](size_t first, size_t last) {
            for (size_t p = first; p < last; ++p)
                if (live[p])
                    store3(normal[p], cross3(_mm_sub_ps(at(uint32_t(4 * p + 2)), at(uint32_t(4 * p))),
                                             _mm_sub_ps(at(uint32_t(4 * p + 3)), at(uint32_t(4 * p + 1)))));
            normalizeAll(normal + first, last - first);
        });
        return;
    }
#endif
    const auto at = s.currentAt();
    for (size_t p = 0; p < P; ++p)
        if (live[p])
            normal[p] = areaNormal(at, s.k.first(p), s.k.last(p));
}

template bool findNormals(FairingState<true> &);
template bool findNormals(FairingState<false> &);
template void findFairedNormals(FairingState<true> &);
template void findFairedNormals(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
