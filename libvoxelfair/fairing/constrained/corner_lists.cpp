// The constrained fairing's connectivity, in one pass over the corners: the corners of live
// polygons at each vertex with their next and previous vertices (a counting sort, CSR), the twin
// of each corner, the creases, and each vertex's sweep wave.
//
// Contract (buildCorners; reads live, normal; fills vertexStart, vertexCorners, vertexNext,
// vertexPrevious, twin, creases/creaseCount, sharpBoundary, and the waves into rank):
// - vertexStart[v] .. vertexStart[v + 1] index v's corners (in corner order); vertexNext and
//   vertexPrevious hold 8 entries of kNone past the last (read by 8-lane loads).
// - twin[c] is the corner of the edge b -> a when c is a -> b and exactly one corner of another
//   polygon runs each way between a and b; otherwise kNone, and c goes to sharpBoundary
//   (boundary, non-manifold or misoriented edges are all kept sharp).
// - creases lists the lower corner of each twinned edge whose polygons' normals meet at more than
//   options.creaseAngleDegrees.
// - rank[v] (used as the wave) is 0 when no neighbour of lower index in v's tile of kTileSize
//   indices comes before it, else one more than the largest such neighbour's wave: vertices of one
//   wave of a tile are never neighbours (sweep_layout.cpp orders the sweeps by it).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {
namespace {

// Index of the bit of 1 << i (i < 8) from (1 << i) * 0x1D >> 5 & 7 (a de Bruijn sequence).
constexpr uint8_t kBitIndex[8] = {0, 1, 6, 2, 7, 5, 4, 3};

}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void buildCorners(FairingState<kQuads> &s) {
    // Counting sort by vertex, the corners cut into ranges (parts): each part counts
    // its corners at each vertex, a serial pass turns the counts into each part's first slot at
    // each vertex (the parts' corners of a vertex follow one another in part order), and each
    // part puts its corners in their slots: every vertex's corners in ascending order, as one
    // pass would, for any number of parts.
    const Polygons<kQuads> k = s.k;
    const size_t V = s.V;
    const uint32_t cornerCount = s.cornerCount, *const indices = s.indices;
    const uint8_t *const live = s.live;
    uint32_t *const start = s.vertexStart, *const corners = s.vertexCorners, *const next = s.vertexNext,
                    *const previous = s.vertexPrevious;
    uint32_t *const twin = s.twin;
    const size_t parts = cornerParts(s.threads.count()), partCorners = (cornerCount + parts - 1) / parts;
    uint32_t *const counts = s.scratch.template take<uint32_t>(parts * V);  // by part, then vertex
    s.threads.run(parts, [&](size_t part) {
        uint32_t *const count = counts + part * V;
        std::fill(count, count + V, 0u);
        const uint32_t first = uint32_t(std::min<size_t>(cornerCount, part * partCorners)),
                       last = uint32_t(std::min<size_t>(cornerCount, (part + 1) * partCorners));
        std::fill(twin + first, twin + last, kNone);  // (a tile writes the twins of its vertices' corners)
        for (uint32_t c = first; c < last; ++c)
            count[indices[c]] += live[k.polygonOf(c)];
    });
    uint32_t begin = 0;
    for (size_t v = 0; v < V; ++v) {
        start[v] = begin;
        for (size_t part = 0; part < parts; ++part) {
            const uint32_t count = counts[part * V + v];
            counts[part * V + v] = begin;
            begin += count;
        }
    }
    start[V] = start[V + 1] = begin;
    s.threads.run(parts, [&](size_t part) {
        uint32_t *const slotOf = counts + part * V;
        const uint32_t first = uint32_t(std::min<size_t>(cornerCount, part * partCorners)),
                       last = uint32_t(std::min<size_t>(cornerCount, (part + 1) * partCorners));
        for (uint32_t c = first; c < last; ++c)
            if (live[k.polygonOf(c)]) {
                const uint32_t slot = slotOf[indices[c]]++;
                corners[slot] = c;
                next[slot] = k.nextVertex(c);
                previous[slot] = k.previousVertex(c);
            }
    });
    std::fill(next + start[V], next + start[V] + 8, kNone);  // read past by the 8-lane loads
    std::fill(previous + start[V], previous + start[V] + 8, kNone);

    // Twins: a -> b and the one edge b -> a, when no other polygon has either direction. Both
    // directions show at a: a -> b as a corner at a whose next vertex is b, b -> a as a corner at a
    // whose previous vertex is b; so a's own list decides. Tile by tile (the waves do not cross
    // tiles), the tiles split between the threads, each listing its creases and corners without
    // twin, joined in tile order: the lists of one pass in vertex order.
    uint32_t *const wave = s.rank;
    const glm::vec3 *const normal = s.normal;
    const float creaseCos = std::cos(s.options.creaseAngleDegrees * 3.14159265f / 180.0f);
    const size_t tiles = (V + kTileSize - 1) / kTileSize;
    std::vector<std::vector<uint32_t>> creasesIn(tiles), boundaryIn(tiles);
    s.threads.run(tiles, [&](size_t tile) {
        const size_t tileStart = tile * kTileSize, tileEnd = std::min(V, tileStart + kTileSize);
        std::fill(wave + tileStart, wave + tileEnd, 0u);
        // On the way: the creases (listed without branching on the test, whose outcome follows no
        // pattern) and the corners without twin.
        std::vector<uint32_t> &boundary = boundaryIn[tile], &tileCreases = creasesIn[tile];
        tileCreases.resize(start[tileEnd] - start[tileStart] + 1);
        uint32_t *const creases = tileCreases.data();
        size_t creaseCount = 0;
        auto noTwin = [&](uint32_t c, bool edge) {
            if (edge)
                boundary.push_back(c);
        };
        // (Each edge's lower corner listed here, the creases among them picked after the loop.)
        auto foundTwin = [&](uint32_t c, uint32_t t) {
            twin[c] = t;
            creases[creaseCount] = c;
            creaseCount += t > c;
        };
        for (size_t a = tileStart; a < tileEnd; ++a) {
            const uint32_t first = start[a], count = start[a + 1] - first;
            // The wave, from the next vertices in the twins' loop below (one loop over the corners:
            // its end, at a count that varies, is a mispredicted branch). (Next vertices are enough:
            // a free vertex has no sharp edge, so every edge a -> u has its twin u -> a, and only
            // free vertices are ordered.)
            uint32_t w = 0;
            auto inWave = [&w, wave, a, tileStart](uint32_t u) {
                // Not branched on: half the neighbours come before, in no pattern. The others read
                // a's own wave, 0 so far (not another tile's, which another thread writes), plus 0.
                // (A mask on the sum, as before, let the compiler branch around the load.)
                const uint32_t before = uint32_t(u < a) & uint32_t(u >= tileStart);
                w = std::max(w, wave[before != 0 ? u : uint32_t(a)] + before);
            };
#ifdef VOXELFAIR_SSE2
            if (count <= 8) {
                // 8 lanes compared at once: where the match is varies, a branch on it would mispredict
                // for most corners. Lanes past `count` hold the next vertices'.
                auto load = [](const uint32_t *x) { return _mm_loadu_si128(reinterpret_cast<const __m128i *>(x)); };
                const __m128i next0 = load(next + first), next1 = load(next + first + 4),
                              previous0 = load(previous + first), previous1 = load(previous + first + 4);
                const unsigned lanes = (1u << count) - 1;
                auto matches = [lanes](__m128i b, __m128i low, __m128i high) {
                    return (unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(b, low)))) |
                            unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(b, high)))) << 4) &
                           lanes;
                };
                for (uint32_t i = 0; i < count; ++i) {
                    const uint32_t b = next[first + i];
                    inWave(b);
                    const __m128i bb = _mm_set1_epi32(int(b));
                    const unsigned out = matches(bb, next0, next1), in = matches(bb, previous0, previous1);
                    // Exactly one each way (out holds i at least).
                    const uint32_t c = corners[first + i];
                    if (b == a || (out & (out - 1)) != 0 || in == 0 || (in & (in - 1)) != 0) {
                        noTwin(c, b != a);
                        continue;
                    }
                    const uint32_t back = kBitIndex[(in * 0x1Du) >> 5 & 7];  // in is a power of 2 below 256
                    const uint32_t t = k.previousCorner(corners[first + back]);
                    if (k.polygonOf(t) != k.polygonOf(c))
                        foundTwin(c, t);
                    else
                        noTwin(c, true);
                }
                wave[a] = w;
                continue;
            }
#endif
            for (uint32_t i = first; i < first + count; ++i) {
                const uint32_t b = next[i];
                inWave(b);
                if (b == a)
                    continue;  // no edge
                uint32_t out = 0, in = 0, back = 0;
                for (uint32_t j = first; j < first + count; ++j) {
                    out += next[j] == b;
                    if (previous[j] == b) {
                        back = j;
                        ++in;
                    }
                }
                const uint32_t c = corners[i], t = k.previousCorner(corners[back]);
                if (out == 1 && in == 1 && k.polygonOf(t) != k.polygonOf(c))
                    foundTwin(c, t);
                else
                    noTwin(c, true);
            }
            wave[a] = w;
        }
        size_t kept = 0;
        for (size_t i = 0; i < creaseCount; ++i) {
            const uint32_t c = creases[i], t = twin[c];
            creases[kept] = c;
#ifdef VOXELFAIR_SSE2
            kept += dot3(load3(normal[k.polygonOf(c)]), load3(normal[k.polygonOf(t)])) < creaseCos;
#else
            kept += glm::dot(normal[k.polygonOf(c)], normal[k.polygonOf(t)]) < creaseCos;
#endif
        }
        tileCreases.resize(kept);
    });
    size_t creaseCount = 0;
    for (size_t tile = 0; tile < tiles; ++tile) {
        std::copy(creasesIn[tile].begin(), creasesIn[tile].end(), s.creases + creaseCount);
        creaseCount += creasesIn[tile].size();
        s.sharpBoundary.insert(s.sharpBoundary.end(), boundaryIn[tile].begin(), boundaryIn[tile].end());
    }
    s.creaseCount = creaseCount;
}

template void buildCorners(FairingState<true> &);
template void buildCorners(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
