// Step 3's memory layout: the Gauss-Seidel order of the constrained fairing split into waves of
// independent vertices, so the sweeps update four at a time (position_kernel.h) with the result
// of the plain order.
//
// Why it is the same result: a sweep updates the free vertices in index order, and all that
// matters for the result is, for each pair of neighbours, which goes first. In index order each
// update mostly waits for the previous one (a neighbour); instead, within each tile of kTileSize
// vertex indices, wave w holds the vertices whose neighbours of lower index in the tile are in
// waves < w (corner_lists.cpp). Sweeping tile after tile and, in each, wave after wave (or all in
// reverse) keeps the order of every pair, and the vertices of a wave never depend on each other.
//
// Contract (buildSlots; reads kind, the waves in rank, vertexStart, vertexNext; the setup's
// temporaries in `scratch` are dead after it): each vertex gets a slot, rank[v]: the free
// vertices tile by tile, wave by wave, each wave padded to whole blocks of four (empty slots,
// vertexAt = kNone), then the other vertices, then one zero slot. Takes step 3's arrays by slot
// (offset zeroed, vertexNormal, filtered, fit, slotNeighbours as byte offsets of the neighbours'
// Offset, the zero slot where fewer than kRegularValence, regularBlock) so a sweep streams
// through memory. Empty slots read the zero slot and have a zero fit: they move by 0. Also each
// tile's vertices grouped by neighbour count (valenceOrder, valenceGroups), for the vertex loops
// of fitFreeVertices and filterNormals: a loop over a count that varies from vertex to vertex in
// no pattern ends in a mispredicted branch (callgrind --branch-sim=yes on the benchmark's sphere:
// 273,000 a call in fitFreeVertices, 114,000 in filterNormals; about 200 after).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

template <bool kQuads>
VOXELFAIR_NOINLINE void buildSlots(FairingState<kQuads> &s) {
    const size_t V = s.V;
    const VertexKind *const kind = s.kind;
    uint32_t *const rank = s.rank, *const wave = s.rank;  // a vertex's wave is read before its rank is set
    // The temporaries are dead: step 3's arrays go in their place, first the slots' vertices.
    s.scratch.rewind({0, 0});
    // Tile by tile, the tiles split between the threads: first each tile's waves' first slots
    // (from the tile's first) and its count of other vertices, then, from the tiles' first slots
    // and first other slots, each vertex's slot.
    const size_t tiles = (V + kTileSize - 1) / kTileSize;
    std::vector<std::vector<uint32_t>> waveStartIn(tiles);
    std::vector<size_t> tileSlot(tiles + 1, 0), tileOther(tiles + 1, 0);
    s.threads.run(tiles, [&](size_t tile) {
        const size_t tileStart = tile * kTileSize, tileEnd = std::min(V, tileStart + kTileSize);
        uint32_t waves = 0;
        size_t others = 0;
        for (size_t v = tileStart; v < tileEnd; ++v) {
            if (isFree(kind[v]))
                waves = std::max(waves, wave[v] + 1);
            else
                ++others;
        }
        std::vector<uint32_t> &waveStart = waveStartIn[tile];
        waveStart.assign(waves + 1, 0);
        for (size_t v = tileStart; v < tileEnd; ++v)
            if (isFree(kind[v]))
                ++waveStart[wave[v] + 1];
        for (uint32_t w = 0; w < waves; ++w)
            waveStart[w + 1] = waveStart[w] + ((waveStart[w + 1] + 3) & ~3u);  // whole blocks
        tileSlot[tile + 1] = waveStart[waves];
        tileOther[tile + 1] = others;
    });
    for (size_t tile = 0; tile < tiles; ++tile) {
        tileSlot[tile + 1] += tileSlot[tile];
        tileOther[tile + 1] += tileOther[tile];
    }
    const size_t freeSlots = s.freeSlots = tileSlot[tiles];
    uint32_t *const vertexAt = s.vertexAt = s.scratch.template take<uint32_t>(freeSlots);
    s.threads.run(tiles, [&](size_t tile) {
        const size_t tileStart = tile * kTileSize, tileEnd = std::min(V, tileStart + kTileSize);
        std::vector<uint32_t> &waveStart = waveStartIn[tile];
        const size_t slots = tileSlot[tile];
        uint32_t other = uint32_t(freeSlots + tileOther[tile]);
        std::fill(vertexAt + slots, vertexAt + tileSlot[tile + 1], kNone);
        for (size_t v = tileStart; v < tileEnd; ++v) {
            if (isFree(kind[v])) {
                const uint32_t slot = uint32_t(slots + waveStart[wave[v]]++);
                vertexAt[slot] = uint32_t(v);
                rank[v] = slot;
            } else {
                rank[v] = other++;
            }
        }
    });
    const uint32_t other = uint32_t(freeSlots + tileOther[tiles]);
    const uint32_t zeroSlot = other;
    s.zeroSlot = zeroSlot;

    s.filtered = s.scratch.template take<glm::vec3>(s.P + 2);
    s.filtered[s.P] = s.filtered[s.P + 1] = glm::vec3(0.0f);
    s.vertexNormal = s.scratch.template take<VertexNormal>(V);
    s.turning = s.scratch.template take<uint8_t>(V);
    std::fill(s.turning, s.turning + V, uint8_t(0));
    // Each tile's vertices by neighbour count (fitFreeVertices, filterNormals: loops of a fixed count).
    uint32_t *const order = s.valenceOrder = s.scratch.template take<uint32_t>(V);
    s.valenceGroups.assign(kValenceGroups * tiles, 0);
    uint32_t *const groups = s.valenceGroups.data();
    {
        const uint32_t *const start = s.vertexStart;
        s.threads.run(tiles, [start, order, groups, V](size_t tile) {
            const size_t tileStart = tile * kTileSize, tileEnd = std::min(V, tileStart + kTileSize);
            auto group = [start](size_t v) {
                const uint32_t count = start[v + 1] - start[v];
                return count >= 3 && count <= kRegularValence ? count - 3 : kRegularValence - 2;
            };
            uint32_t *const first = groups + kValenceGroups * tile;  // counts, then each group's first
            for (size_t v = tileStart; v < tileEnd; ++v)
                ++first[group(v) + 1];
            first[0] = uint32_t(tileStart);
            for (size_t g = 1; g < kValenceGroups; ++g)
                first[g] += first[g - 1];
            uint32_t fill[kValenceGroups];
            std::copy(first, first + kValenceGroups, fill);
            for (size_t v = tileStart; v < tileEnd; ++v)
                order[fill[group(v)]++] = uint32_t(v);
        });
    }
    s.slotNeighbours = s.scratch.template take<uint32_t>(kRegularValence * freeSlots);
    s.offset = s.scratch.template take<Offset>(zeroSlot + 1);
    Offset *const offset = s.offset;
    s.threads.forRanges(zeroSlot + 1, 4 * kTileSize, [offset](size_t first, size_t last) {
        std::fill(offset + first, offset + last, Offset{0.0f, glm::vec3(0.0f)});
    });
    s.fit = s.scratch.template take<FitBlock>(freeSlots / 4);
    s.regularBlock = s.scratch.template take<uint8_t>(freeSlots / 4);
    // (moveFreeBlock reads slotNeighbours as byte offsets, which must fit 32 bits: beyond 2^28
    // slots every vertex goes through the general path.)
    const bool regularFits = zeroSlot < (1u << 28);
    std::fill(s.regularBlock, s.regularBlock + freeSlots / 4, uint8_t(regularFits));  // see fitFreeVertices
    // Free vertices' neighbours by slot (vertex by vertex: the neighbours' ranks are near in memory).
    uint32_t *const slotNeighbours = s.slotNeighbours;
    const uint32_t *const start = s.vertexStart, *const next = s.vertexNext;
    // (Vertex ranges, then slot ranges, split between the threads: each writes its own slots.)
    s.threads.forRanges(V, 4096, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            if (!isFree(kind[v]))
                continue;
            uint32_t *out = slotNeighbours + kRegularValence * size_t(rank[v]);
            const uint32_t count = kind[v] == VertexKind::Free ? start[v + 1] - start[v] : 0;
            for (uint32_t i = 0; i < kRegularValence; ++i) {
                // (Selected, not branched on: the count varies in no pattern.)
                const uint32_t neighbour = rank[next[start[v] + std::min(i, std::max(count, 1u) - 1)]];
                out[i] = uint32_t(sizeof(Offset)) * (i < count ? neighbour : zeroSlot);
            }
        }
    });
    s.threads.forRanges(freeSlots / 4, 1024, [&](size_t firstBlock, size_t lastBlock) {
        for (size_t slot = 4 * firstBlock; slot < 4 * lastBlock; ++slot) {
            if (vertexAt[slot] != kNone)
                continue;
            std::fill(slotNeighbours + kRegularValence * slot, slotNeighbours + kRegularValence * (slot + 1),
                      uint32_t(sizeof(Offset)) * zeroSlot);
            FitBlock &f = s.fit[slot / 4];
            const int lane = int(slot % 4);
            f.stepScale[lane] = f.nx[lane] = f.ny[lane] = f.nz[lane] = 0.0f;
            f.base[lane] = f.sx[lane] = f.sy[lane] = f.sz[lane] = 0.0f;
        }
    });
}

template void buildSlots(FairingState<true> &);
template void buildSlots(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
