// Step 2 of the constrained fairing (constrained_fairing.h): polygon normals averaged with their
// neighbours across smooth edges, never across a sharp one.
//
// Why it works on a staircase: the sum of unit face normals over a patch is the true normal times
// the patch's projected area, so averaging removes the steps without bias, and a sphere's averaged
// normals stay radial (no shrinking). A trous (Holschneider et al., "A real-time algorithm for
// signal analysis with the help of the wavelet transform", 1989): level i averages each polygon
// with the four polygons 2^i quads straight across its edges, so 3 levels reach as far as about
// 12 plain sweeps.
//
// Contract (buildLevels; reads twin, sharpBoundary, sharpCreases; turns twin into level 0 and
// fills levels 1 .. storedLevels - 1 after it): level i of corner c is the corner by which a walk
// straight across c's edge enters the polygon 2^i quads away; kNone when a sharp edge, a hole or
// a non-quad is in the way (at level 0: the twin across smooth edges, any polygon). Level i + 1
// is level i taken twice (pointer doubling); the top level, used only by the first pass, is
// looked up through the level below (FairingState::doubled). From level 1 on, no walk crosses an
// notch edge (FairingState::notches: a turned box's corner, edge_classes.cpp): the faces beside it average their
// normals with the corner's only at level 0, one quad deep, and stay flat.
//
// Contract (filterNormals; reads normal, the level tables, the corner lists; fills normal,
// vertexNormal): `levels` Jacobi rounds, each normal[p] <- normalize(normal[p] + the four level-i
// neighbours' normals, a missing one counting as zero); then vertexNormal[v] = normalize(sum of
// v's polygons' filtered normals), summed in polygon order. The quad path gives the same bits as
// the general one; polygons and vertices are split between the threads (stage_threads.h).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <utility>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {
constexpr size_t kGrain = 4096;  // polygons or vertices a thread takes at a time (a multiple of 4)
}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void buildLevels(FairingState<kQuads> &s) {
    uint32_t *const twin = s.twin;
    for (const std::vector<uint32_t> *edges : {&s.sharpBoundary, &s.sharpCreases})
        for (uint32_t c : *edges)
            if (twin[c] != kNone) {
                twin[twin[c]] = kNone;
                twin[c] = kNone;
            }
    for (int level = 1; level < s.storedLevels; ++level) {
        const uint32_t *below = s.levelTable(level - 1);
        uint32_t *table = twin + size_t(level) * s.cornerCount;
        // (Corner ranges split between the threads: each corner's entry is its own.)
        s.threads.forRanges(s.cornerCount, 4 * kGrain, [&](size_t first, size_t last) {
            for (size_t c = first; c < last; ++c)
                table[c] = s.doubled(below, uint32_t(c));
        });
        if (level != 1)
            continue;
        // No walk of 2 quads (and so none further) across a notch edge: not from either of its
        // corners n, nor from the corner whose level-0 walk ends across from n (level 0 is its own
        // inverse), which would cross n's edge second.
        for (uint32_t c : s.notches)
            for (uint32_t n : {c, twin[c]}) {
                if (n == kNone)
                    continue;
                table[n] = kNone;
                if (s.k.inQuad(n) && below[s.k.oppositeCorner(n)] != kNone)
                    table[below[s.k.oppositeCorner(n)]] = kNone;
            }
    }
}

namespace {

#ifdef VOXELFAIR_SSE2
// One level of filterNormals on the quads [first, last), a normal per register and four
// normalized at once (a square root and a division each otherwise make up most of the time):
// the same sums and products, so the same results. Loads and stores of 16 bytes at the 12-byte
// normals read one float past (arrays of P + 2) and write 0 into the next normal's x (its own
// turn comes next; [P] stays 0), but the last of the range, whose next may be another thread's.
template <bool kQuads>
VOXELFAIR_NOINLINE void filterQuads(FairingState<kQuads> &s, const uint32_t *table, bool composed, size_t first,
                                    size_t last) {
    const glm::vec3 *const normal = s.normal;
    glm::vec3 *const filtered = s.filtered;
    const uint32_t none = uint32_t(s.P);
    const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
    auto load = [&](uint32_t p) { return _mm_loadu_ps(&normal[p].x); };
    auto sumAround = [&](size_t p) {
        const uint32_t *entry = table + 4 * p;
        __m128 sum = load(uint32_t(p));
        for (uint32_t i = 0; i < 4; ++i) {
            uint32_t e = entry[i];
            if (composed && e != kNone)
                e = table[e ^ 2u];
            sum = _mm_add_ps(sum, load(e != kNone ? e >> 2 : none));
        }
        return _mm_and_ps(sum, xyz);
    };
    auto store = [&](size_t p, __m128 unit) {
        if (p + 1 == last)
            store3(filtered[p], unit);
        else
            _mm_storeu_ps(&filtered[p].x, unit);
    };
    size_t p = first;
    for (; p + 4 <= last; p += 4) {
        __m128 a = sumAround(p), b = sumAround(p + 1), c = sumAround(p + 2), d = sumAround(p + 3);
        normalizeFour(a, b, c, d);
        store(p, a);
        store(p + 1, b);
        store(p + 2, c);
        store(p + 3, d);
    }
    for (; p < last; ++p) {
        __m128 a = sumAround(p), b = a, c = a, d = a;
        normalizeFour(a, b, c, d);
        store(p, a);
    }
}
#endif

// vertexNormal[v] = the sum of the normals of v's polygons (in polygon order, as a loop over the
// polygons adding to their vertices would sum them), for the vertices order[first, last), each with
// kCount polygons when kCount > 0 (a loop of a fixed count: its end no branch that varies).
template <uint32_t kCount, bool kQuads>
void sumAtVertices(FairingState<kQuads> &s, const glm::vec3 *normal, const uint32_t *order, uint32_t first,
                   uint32_t last) {
    const uint32_t *const start = s.vertexStart, *const corners = s.vertexCorners;
    VertexNormal *const vertexNormal = s.vertexNormal;
    const Polygons<kQuads> k = s.k;
    for (uint32_t i = first; i < last; ++i) {
        const uint32_t v = order[i], begin = start[v], end = kCount > 0 ? begin + kCount : start[v + 1];
#ifdef VOXELFAIR_SSE2
        __m128 sum = _mm_setzero_ps();  // lane 3 masked off: the normals are read 16 bytes at a time
        for (uint32_t j = begin; j < end; ++j)
            sum = _mm_add_ps(sum, _mm_loadu_ps(&normal[k.polygonOf(corners[j])].x));
        _mm_store_ps(&vertexNormal[v].n.x, _mm_and_ps(sum, _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1))));
#else
        glm::vec3 sum(0.0f);
        for (uint32_t j = begin; j < end; ++j)
            sum += normal[k.polygonOf(corners[j])];
        vertexNormal[v] = VertexNormal{sum, 0.0f};
#endif
    }
}

}  // namespace

// (Polygons that are not live are on no vertex's corner list; their filtered normals are 0, so
// adding them would change no sum.)
template <bool kQuads>
VOXELFAIR_NOINLINE void filterNormals(FairingState<kQuads> &s, int levels) {
    const Polygons<kQuads> k = s.k;
    StageThreads &threads = s.threads;
    for (int level = 0; level < levels; ++level) {
        const bool composed = level == s.storedLevels;  // the top level of the first pass
        const uint32_t *table = s.levelTable(composed ? level - 1 : level);
        threads.forRanges(s.P, kGrain, [&](size_t first, size_t last) {
#ifdef VOXELFAIR_SSE2
            if constexpr (kQuads) {
                filterQuads(s, table, composed, first, last);
                return;
            }
#endif
            for (size_t p = first; p < last; ++p) {
                glm::vec3 sum = s.normal[p];
                for (uint32_t c = k.first(p); c < k.last(p); ++c) {
                    const uint32_t e = composed ? s.doubled(table, c) : table[c];
                    sum += s.normal[e != kNone ? k.polygonOf(e) : uint32_t(s.P)];
                }
                s.filtered[p] = normalizedOrZero(sum);
            }
        });
        std::swap(s.normal, s.filtered);
    }
    // (Tile by tile, the vertices by their polygons' count: FairingState::valenceOrder.)
    threads.forRanges(s.V, kTileSize, [&](size_t first, size_t last) {
        const uint32_t *const order = s.valenceOrder, *const group =
                                                          s.valenceGroups.data() + kValenceGroups * (first / kTileSize);
        sumAtVertices<3>(s, s.normal, order, group[0], group[1]);
        sumAtVertices<4>(s, s.normal, order, group[1], group[2]);
        sumAtVertices<5>(s, s.normal, order, group[2], group[3]);
        sumAtVertices<6>(s, s.normal, order, group[3], group[4]);
        sumAtVertices<0>(s, s.normal, order, group[4], group[5]);
        normalizeAll(&s.vertexNormal[first].n, last - first, sizeof(VertexNormal));
    });
}

template void buildLevels(FairingState<true> &);
template void buildLevels(FairingState<false> &);
template void filterNormals(FairingState<true> &, int);
template void filterNormals(FairingState<false> &, int);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
