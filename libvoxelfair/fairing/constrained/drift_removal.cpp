// Step 5 of the constrained fairing (constrained_fairing.h): the drift along the normals taken off.
//
// Why: step 3 only asks edges to be perpendicular to normals, so a face can slide along its
// normal and a part can grow; near edges and fillets, whose filtered normals turn over more quads
// than the true surface does, the cells push the rounded profile out and drag the flat faces with
// it (a rounded box became a pillow, +3.8% volume). So each vertex's displacement along its
// normal, n . d, is averaged over its neighbourhood and that local mean is taken off: the surface
// keeps the voxels' volume locally, as the voxelization of a plane or a smooth surface does on
// average.
//
// Two scales (ours). The mean over `rounds` Jacobi rounds (8: a few rings) is what holds faces
// beside edges and fillets flat, but on a smooth surface it still carries some of the staircase's
// ripple, which subtracting it puts back. Far from where the shape turns, the mean over
// `wideRounds` rounds (24) is taken off instead: on the curved families of
// testkit/shapes/shape_families.h (spheres, ellipsoids, tori, capsules at random orientations,
// 8 instances each) the worst RMS drops from 0.071-0.078 to 0.063-0.069 voxels, and no family
// gets worse by more than 0.001 (tests/fairing/family_fidelity_test.cpp). Where the shape turns:
// a vertex that is not free (edge lines, pinned), whose normal is more than kTurnDegrees from a
// neighbour's (an edge or a fillet the staircase hides; a sphere of radius 5 turns about 11
// degrees a quad), or whose normal is within kLatticeDegrees of a lattice axis (a face on a
// lattice plane, exact already, beside a fillet: the wide mean would carry the fillet's drift
// onto it). That mark is averaged over `rounds` rounds too, and the local mean weighs
// min(1, kNearGain * mark): the local one within a few rings of any marked vertex, blending into
// the wide one beyond.
//
// Contract (removeDrift; reads offset, fit (the last pass's normals, which equal vertexNormal's
// bits, slot by slot), vertexNormal, kind, the corner lists and the slots; writes offset[.].d of
// the free vertices, not those held on planes; turns slotNeighbours' byte offsets into slots, for
// the sweeps are done): each vertex's n . d (0 for those that do not
// move), by slot, is averaged with its neighbours' (Jacobi, over slots: regular blocks read their
// padded neighbour lists, the rest their corner lists; the same sums in the same order either way,
// four regular slots at once in SSE); the blend above is taken off along n, clamped into the cell
// (step 4). With wideRounds <= rounds, the local mean alone (bit for bit the one-scale step).
// The mark's rounds visit only the vertices within reach of a marked one when they are few (a
// large smooth surface: 45 marked vertices of 98,582 on the benchmark's sphere), with the same
// result (averageNearMarks).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {

constexpr float kTurnDegrees = 15.0f;    // a neighbour's normal this far: the shape turns here
constexpr float kLatticeDegrees = 1.0f;  // a normal this near a lattice axis: a lattice face
constexpr float kNearGain = 50.0f;       // the averaged mark at which the local mean takes over
constexpr size_t kBlockGrain = 1024;     // blocks (or other vertices) a thread takes at a time

// One Jacobi round at vertex v over its corner list, by slot: its value and its neighbours',
// summed in the corner list's order, times its weight (1 / (1 + valence)). Every path below sums
// in this order, so they agree bit for bit.
template <bool kQuads>
inline float cornerListMean(const FairingState<kQuads> &s, const float *values, const float *weight, uint32_t v) {
    float sum = values[s.rank[v]];
    for (uint32_t j = s.vertexStart[v]; j < s.vertexStart[v + 1]; ++j)
        sum += values[s.rank[s.vertexNext[j]]];
    return sum * weight[s.rank[v]];
}

// One Jacobi round on the regular blocks [firstBlock, lastBlock): each slot's value and its
// neighbours' (the padded lists of sweep_layout.cpp: slots times 2^kShift), summed in the
// corner list's order, times its weight, into `spare`.
template <int kShift>
inline void averageRegularBlocks(const float *values, float *spare, const float *weight, const uint32_t *neighbours,
                                 const uint8_t *regular, size_t firstBlock, size_t lastBlock) {
    for (size_t block = firstBlock; block < lastBlock; ++block) {
        if (!regular[block])
            continue;
#ifdef VOXELFAIR_SSE2
        // The four slots' sums side by side, each in the order below.
        const uint32_t *n = neighbours + kRegularValence * 4 * block;
        auto gather = [&](uint32_t i) {
            return _mm_setr_ps(values[n[i] >> kShift], values[n[kRegularValence + i] >> kShift],
                               values[n[2 * kRegularValence + i] >> kShift],
                               values[n[3 * kRegularValence + i] >> kShift]);
        };
        __m128 sum = _mm_load_ps(values + 4 * block);
        for (uint32_t i = 0; i < kRegularValence; ++i)
            sum = _mm_add_ps(sum, gather(i));
        _mm_store_ps(spare + 4 * block, _mm_mul_ps(sum, _mm_load_ps(weight + 4 * block)));
        continue;
#endif
        for (size_t slot = 4 * block; slot < 4 * block + 4; ++slot) {
            const uint32_t *n = neighbours + kRegularValence * slot;
            float sum = values[slot];
            for (uint32_t i = 0; i < kRegularValence; ++i)
                sum += values[n[i] >> kShift];
            spare[slot] = sum * weight[slot];
        }
    }
}

}  // namespace

// `rounds` rounds of the mean on `values` (the marks, by slot: 1 at the vertices `marked`, 0
// elsewhere), the result in `values`; `spare` as large. After round r only the vertices within r
// edges of a marked one can be non-zero, so when those are few (a large smooth surface) only
// they are averaged, each over its corner list: the same sums in the same order as `dense` (the
// padded lists only add the zero slot's 0 after them, and the marks' means are not negative),
// the same result bit for bit. Otherwise `dense` runs the rounds.
template <bool kQuads, class Dense>
void averageNearMarks(const FairingState<kQuads> &s, const float *weight, const std::vector<uint32_t> &marked,
                      int rounds, float *&values, float *&spare, Dense &&dense) {
    const uint32_t *const start = s.vertexStart, *const next = s.vertexNext, *const rank = s.rank;
    const size_t limit = s.V / 4;  // beyond this many vertices in reach, the dense rounds
    // The vertices within `rounds` edges of a marked one, nearest first; reach[r]: how many are
    // within r edges.
    std::vector<uint32_t> active;
    std::vector<size_t> reach;
    if (marked.size() <= limit && rounds > 0) {
        std::vector<uint8_t> seen(s.V, 0);
        active = marked;
        for (uint32_t v : marked)
            seen[v] = 1;
        reach.push_back(active.size());
        for (int r = 1; r <= rounds && active.size() <= limit; ++r) {
            for (size_t i = r == 1 ? 0 : reach[size_t(r - 2)]; i < reach[size_t(r - 1)]; ++i)
                for (uint32_t j = start[active[i]]; j < start[active[i] + 1]; ++j)
                    if (!seen[next[j]]) {
                        seen[next[j]] = 1;
                        active.push_back(next[j]);
                    }
            reach.push_back(active.size());
        }
    }
    if (reach.size() != size_t(rounds) + 1 || active.size() > limit) {
        dense(values, spare, rounds);
        return;
    }
    // Slots out of reach of round r read 0 in both buffers: `spare` starts at 0.
    std::fill(spare, spare + s.zeroSlot + 1, 0.0f);
    for (int r = 1; r <= rounds; ++r) {
        for (size_t i = 0; i < reach[size_t(r)]; ++i)
            spare[rank[active[i]]] = cornerListMean(s, values, weight, active[i]);
        std::swap(values, spare);
    }
}

// `count` rounds on `values` (by slot; `spare` as large), the result in `values`; run(chunks,
// chunk) calls chunk(c) for each c (on the stage's threads, or one after another).
// The same sums in the same order as over each vertex's corner list: a regular block's lists
// (sweep_layout.cpp) are that list padded with the zero slot, whose 0 adds nothing.
// Each round's slots are independent (Jacobi): the blocks and the other vertices split
// between the threads, the same sums either way. kShift 4 while the lists still hold the
// sweeps' byte offsets, 0 once they hold slots.
template <int kShift, bool kQuads, class Run>
void averageRounds(const FairingState<kQuads> &s, float *&values, float *&spare, int count, Run &&run) {
    const DriftArrays &d = s.drift;
    const size_t blocks = s.freeSlots / 4, otherCount = d.otherCount;
    const uint32_t *const neighbours = s.slotNeighbours, *const others = d.others, *const rank = s.rank;
    const uint8_t *const regular = s.regularBlock;
    const float *const weight = d.weight;
    static_assert(sizeof(Offset) == size_t(1) << 4, "byte offsets to slots");
    // (One run a round: the blocks' chunks, then the other vertices'.)
    const size_t blockChunks = (blocks + kBlockGrain - 1) / kBlockGrain;
    const size_t chunks = blockChunks + (otherCount + kBlockGrain - 1) / kBlockGrain;
    for (int round = 0; round < count; ++round) {
        run(chunks, [&, values, spare](size_t chunk) {
            if (chunk >= blockChunks) {
                const size_t first = (chunk - blockChunks) * kBlockGrain;
                for (size_t i = first; i < std::min(otherCount, first + kBlockGrain); ++i)
                    spare[rank[others[i]]] = cornerListMean(s, values, weight, others[i]);
                return;
            }
            averageRegularBlocks<kShift>(values, spare, weight, neighbours, regular, chunk * kBlockGrain,
                                         std::min(blocks, (chunk + 1) * kBlockGrain));
        });
        std::swap(values, spare);
    }
}

template <bool kQuads>
void takeDriftArrays(FairingState<kQuads> &s, int rounds, int wideRounds) {
    const size_t slots = s.zeroSlot + 1;
    DriftArrays &d = s.drift;
    d.along = s.scratch.template take<float>(slots);
    d.smooth = s.scratch.template take<float>(slots);
    d.weight = s.scratch.template take<float>(slots);
    d.others = s.scratch.template take<uint32_t>(s.V);
    d.otherCount = 0;
    if (wideRounds > rounds) {
        d.local = s.scratch.template take<float>(slots);
        d.near = s.scratch.template take<float>(slots);
        d.nearSpare = s.scratch.template take<float>(slots);
    }
}

template <bool kQuads>
VOXELFAIR_NOINLINE void prepareDrift(FairingState<kQuads> &s, int rounds, int wideRounds) {
    const size_t V = s.V, slots = s.zeroSlot + 1;
    const uint32_t *const start = s.vertexStart, *const next = s.vertexNext, *const rank = s.rank;
    const uint8_t *const regular = s.regularBlock;
    const VertexKind *const kind = s.kind;
    DriftArrays &d = s.drift;
    // Empty slots and the zero slot have weight 0 and stay 0; n . d is 0 for those that do not move.
    float *const weight = d.weight;
    std::fill(d.along, d.along + slots, 0.0f);
    std::fill(d.smooth, d.smooth + slots, 0.0f);
    std::fill(weight, weight + slots, 0.0f);
    // The vertices that are not free, or free outside regular blocks, in vertex order.
    uint32_t *const others = d.others;
    size_t otherCount = 0;
    for (size_t v = 0; v < V; ++v) {
        const uint32_t slot = rank[v];
        weight[slot] = 1.0f / float(1 + start[v + 1] - start[v]);
        if (!isFree(kind[v]) || !regular[slot / 4])
            others[otherCount++] = uint32_t(v);
    }
    d.otherCount = otherCount;
    if (wideRounds <= rounds)
        return;
    // Where the shape turns (see above), by slot; the zero slot stays 0.
    float *near = d.near, *spare = d.nearSpare;
    std::fill(near, near + slots, 0.0f);
    std::fill(spare, spare + slots, 0.0f);
    const VertexNormal *const vertexNormal = s.vertexNormal;
    const float turnCos = std::cos(glm::radians(kTurnDegrees));
    const float latticeCos = std::cos(glm::radians(kLatticeDegrees));
    std::vector<uint32_t> marked;
    for (size_t v = 0; v < V; ++v) {
        const glm::vec3 n = vertexNormal[v].n, a = glm::abs(n);
        bool turns = !isFree(kind[v]) || std::max(a.x, std::max(a.y, a.z)) > latticeCos;
        for (uint32_t j = start[v]; !turns && j < start[v + 1]; ++j)
            turns = glm::dot(n, vertexNormal[next[j]].n) < turnCos;
        near[rank[v]] = turns ? 1.0f : 0.0f;
        if (turns)
            marked.push_back(uint32_t(v));
    }
    // (Beside the sweeps: their byte offsets still in the lists, the rounds one after another.)
    averageNearMarks(s, weight, marked, rounds, near, spare, [&](float *&values, float *&other, int count) {
        averageRounds<4>(s, values, other, count, [](size_t chunks, auto &&chunk) {
            for (size_t c = 0; c < chunks; ++c)
                chunk(c);
        });
    });
    d.near = near;
}

template <bool kQuads>
VOXELFAIR_NOINLINE void removeDrift(FairingState<kQuads> &s, int rounds, int wideRounds) {
    const size_t V = s.V, slots = s.zeroSlot + 1;
    const uint32_t *const vertexAt = s.vertexAt;
    uint32_t *const neighbours = s.slotNeighbours;
    Offset *const offset = s.offset;
    StageThreads &threads = s.threads;
    threads.joinAside();  // prepareDrift, beside the last pass's sweeps
    const DriftArrays &d = s.drift;
    float *along = d.along, *smooth = d.smooth;
    // (A free vertex's normal is its lane's in `fit`, slot by slot; empty slots' are 0.)
    const FitBlock *const fit = s.fit;
    // (The sweeps are done: their byte offsets in slotNeighbours become slots, one instruction less
    // a neighbour in the rounds.)
    threads.forRanges(s.freeSlots, 4 * kBlockGrain, [&](size_t first, size_t last) {
        for (size_t block = first / 4; block < last / 4; ++block)
            alongNormalOfBlock(fit[block], offset + 4 * block, along + 4 * block);
        for (size_t i = kRegularValence * first; i < kRegularValence * last; ++i)
            neighbours[i] /= uint32_t(sizeof(Offset));
    });
    auto onThreads = [&threads](size_t chunks, auto &&chunk) { threads.run(chunks, chunk); };
    averageRounds<0>(s, along, smooth, rounds, onThreads);
    if (wideRounds > rounds) {
        float *const local = d.local;
        threads.forRanges(slots, 4 * kBlockGrain, [along, local](size_t first, size_t last) {
            std::copy(along + first, along + last, local + first);
        });
        averageRounds<0>(s, along, smooth, wideRounds - rounds, onThreads);
        const float *const near = d.near;
        threads.forRanges(s.freeSlots, 4 * kBlockGrain, [&](size_t first, size_t last) {
            for (size_t slot = first; slot < last; ++slot) {
                const float t = std::min(1.0f, kNearGain * near[slot]);
                along[slot] = t * local[slot] + (1.0f - t) * along[slot];
            }
        });
    }
    std::vector<uint8_t> held(s.anchored.empty() ? 0 : V, 0);
    for (uint32_t v : s.anchored)
        held[v] = 1;
    const float half = s.half;
    threads.forRanges(s.freeSlots, 4 * kBlockGrain, [&](size_t first, size_t last) {
#ifdef VOXELFAIR_SSE2
        if (held.empty()) {
            // Four slots at once: the same products, differences and clamps as below.
            const __m128 lo = _mm_set1_ps(-half), hi = _mm_set1_ps(half);
            for (size_t block = first / 4; block < last / 4; ++block) {
                Offset *const own = offset + 4 * block;
                const FitBlock &f = fit[block];
                __m128 a = _mm_load_ps(&own[0].alongNormal), dx = _mm_load_ps(&own[1].alongNormal),
                       dy = _mm_load_ps(&own[2].alongNormal), dz = _mm_load_ps(&own[3].alongNormal);
                _MM_TRANSPOSE4_PS(a, dx, dy, dz);
                // (Empty slots keep their offset: lanes whose vertex is kNone.)
                const __m128 keep = _mm_castsi128_ps(_mm_cmpeq_epi32(
                    _mm_loadu_si128(reinterpret_cast<const __m128i *>(vertexAt + 4 * block)), _mm_set1_epi32(-1)));
                const __m128 t = _mm_load_ps(along + 4 * block);
                auto moved = [&](__m128 d, const float *n) {
                    const __m128 x = _mm_min_ps(_mm_max_ps(_mm_sub_ps(d, _mm_mul_ps(t, _mm_load_ps(n))), lo), hi);
                    return _mm_or_ps(_mm_and_ps(keep, d), _mm_andnot_ps(keep, x));
                };
                dx = moved(dx, f.nx);
                dy = moved(dy, f.ny);
                dz = moved(dz, f.nz);
                _MM_TRANSPOSE4_PS(a, dx, dy, dz);
                _mm_store_ps(&own[0].alongNormal, a);
                _mm_store_ps(&own[1].alongNormal, dx);
                _mm_store_ps(&own[2].alongNormal, dy);
                _mm_store_ps(&own[3].alongNormal, dz);
            }
            return;
        }
#endif
        for (size_t slot = first; slot < last; ++slot) {
            const uint32_t v = vertexAt[slot];
            if (v != kNone && (held.empty() || !held[v])) {
                Offset &o = offset[slot];
                o.d = glm::clamp(o.d - along[slot] * fit[slot / 4].n(int(slot % 4)), -half, half);
            }
        }
    });
}

template void takeDriftArrays(FairingState<true> &, int, int);
template void takeDriftArrays(FairingState<false> &, int, int);
template void prepareDrift(FairingState<true> &, int, int);
template void prepareDrift(FairingState<false> &, int, int);
template void removeDrift(FairingState<true> &, int, int);
template void removeDrift(FairingState<false> &, int, int);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
