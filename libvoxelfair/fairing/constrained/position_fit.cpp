// Steps 3 and 4 of the constrained fairing (constrained_fairing.h): the vertices are moved to fit
// the filtered normals, each inside the cell around its input position.
//
// Step 3 follows Sun, Rosin, Martin and Langbein, "Fast and effective feature-preserving mesh
// denoising" (IEEE TVCG 13(5), 2007). A free vertex v with normal n moves along n so that each
// edge v-u becomes perpendicular to s = n + n_u (the bisector of the two normals, which holds
// exactly on a sphere): least squares along n gives a move of 2 sum s.(x_u - x_v) / sum |s|^2.
// A neighbour that is not free lends n (s = 2n); one more than 90 degrees away (another sheet) is
// left out (an edge is used when |s|^2 > 2), and its vertex goes through the general path from
// then on. With x = input + d and n_u . d_u kept per vertex,
//     sum s.(x_u - x_v) = base + n . sum d_u + sum n_u . d_u - sumS . d_v,
// so a sweep reads only the neighbours' offsets (position_kernel.h). A vertex on a sharp edge
// line moves towards the planes of its polygons through their centroids (keeps the edge sharp).
//
// Step 4 (Gibson, "Constrained elastic surface nets", MICCAI 1998): on the voxel surface the true
// surface crosses the cube spanned by the 8 voxel centres around each lattice vertex, so every
// vertex stays within `half` of its input position per axis. This bounds every move, keeps
// 1-voxel plates and rods from collapsing, and keeps the volume.
//
// Contract: fitFreeVertices (reads vertexNormal, input, kind; fills fit, regularBlock, offset's
// alongNormal, and turning / anyTurning: a neighbour's normal more than featureSpread away, for
// feature_fit.cpp) prepares one pass; sweep(forward) runs one Gauss-Seidel sweep, edge-line vertices
// then free ones, in slot order or its reverse, each clamped into its cell as it moves; finish
// writes input + offset to the free and edge-line vertices and the report's counts. Step 5
// (removeDrift) is in drift_removal.cpp.
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <type_traits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {
constexpr size_t kVertexGrain = 4096;  // vertices (or slots) a thread takes at a time
}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void fitFreeVertices(FairingState<kQuads> &s) {
    // Vertex by vertex (neighbours' data are near in memory), into the slots' blocks; the empty
    // slots' lanes were zeroed in buildSlots.
    VertexKind *const kind = s.kind;
    const VertexNormal *const vertexNormal = s.vertexNormal;
    const glm::vec3 *const input = s.input;
    const uint32_t *const rank = s.rank, *const start = s.vertexStart, *const next = s.vertexNext;
    FitBlock *const fit = s.fit;
    uint8_t *const regularBlock = s.regularBlock;
    // Step 3b's feature vertices (feature_fit.cpp): a neighbour's normal more than featureSpread
    // away, |n + n_u|^2 = 2 + 2 cos(angle) below its bound.
    uint8_t *const turning = s.turning;
    const float turned = 2.0f + 2.0f * std::cos(glm::radians(s.options.featureSpreadDegrees));
    std::atomic<bool> anyTurning{false};
    // Vertex by vertex, each writing its own slot's lane, tile by tile split between the threads:
    // a block's slots are of one tile's vertices (sweep_layout.cpp), so a tile's vertices alone
    // write its blocks' flags.
    s.threads.forRanges(
        s.V, kTileSize,
        [&, kind0 = kind, vertexNormal0 = vertexNormal, input0 = input, rank0 = rank, start0 = start, next0 = next,
         fit0 = fit, regularBlock0 = regularBlock, turning0 = turning, turned0 = turned, valenceOrder0 = s.valenceOrder,
         valenceGroups0 = s.valenceGroups.data()](size_t firstVertex, size_t) {
            // (Locals: the byte stores below could alias the closure's copies.)
            VertexKind *const kind = kind0;
            const VertexNormal *const vertexNormal = vertexNormal0;
            const glm::vec3 *const input = input0;
            const uint32_t *const rank = rank0, *const start = start0, *const next = next0;
            FitBlock *const fit = fit0;
            uint8_t *const regularBlock = regularBlock0, *const turning = turning0;
            const float turned = turned0;
            bool turns = false;
            // One vertex; its neighbours' count a constant where kCount > 0 (the
            // loop's end then no branch that varies from vertex to vertex).
            auto fitVertex = [&](uint32_t v, auto used) {
                constexpr uint32_t kCount = decltype(used)::value;
                if (!isFree(kind[v]))
                    return;
                const uint32_t first = start[v], count = kCount > 0 ? kCount : start[v + 1] - first;
                float sum2 = 0.0f, base = 0.0f, minE2 = 4.0f;
                bool allUsed = true;
#ifdef VOXELFAIR_SSE2
                // (Vertex normals are 16-byte blocks with a zero fourth float: whole loads.)
                auto normalOf = [vertexNormal](uint32_t u) { return _mm_load_ps(&vertexNormal[u].n.x); };
                const __m128 n = normalOf(uint32_t(v)), x = load3(input[v]);
                __m128 sumS = _mm_setzero_ps(), products = sumS;  // base: the sum of products' lanes
                for (uint32_t i = first; i < first + count; ++i) {
                    const uint32_t u = next[i];
                    const __m128 e = _mm_add_ps(n, isFree(kind[u]) ? normalOf(u) : n);
                    const float e2 = dot3(e, e);
                    minE2 = std::min(minE2, e2);
                    if (!(e2 > 2.0f)) {
                        allUsed = false;
                        continue;
                    }
                    sum2 += e2;
                    sumS = _mm_add_ps(sumS, e);
                    products = _mm_add_ps(products, _mm_mul_ps(e, _mm_sub_ps(load3(input[u]), x)));
                }
                base = dot3(products, _mm_set1_ps(1.0f));
                alignas(16) float nOut[4], sOut[4];
                _mm_store_ps(nOut, n);
                _mm_store_ps(sOut, sumS);
#else
                const glm::vec3 n = vertexNormal[v].n;
                glm::vec3 sumS(0.0f);
                for (uint32_t i = first; i < first + count; ++i) {
                    const uint32_t u = next[i];
                    const glm::vec3 e = s.edgeTerm(n, u);
                    const float e2 = glm::dot(e, e);
                    minE2 = std::min(minE2, e2);
                    if (!(e2 > 2.0f)) {
                        allUsed = false;
                        continue;
                    }
                    sum2 += e2;
                    sumS += e;
                    base += glm::dot(e, input[u] - input[v]);
                }
                const float nOut[3] = {n.x, n.y, n.z}, sOut[3] = {sumS.x, sumS.y, sumS.z};
#endif
                const uint32_t slot = rank[v];
                turning[v] = minE2 < turned;
                turns = turns || minE2 < turned;
                if (!allUsed)
                    kind[v] = VertexKind::FreeIrregular;
                if (kind[v] != VertexKind::Free)
                    regularBlock[slot / 4] = 0;
                FitBlock &f = fit[slot / 4];
                const int lane = int(slot % 4);
                f.stepScale[lane] = sum2 > 0.0f ? 2.0f / sum2 : 0.0f;
                f.nx[lane] = nOut[0];
                f.ny[lane] = nOut[1];
                f.nz[lane] = nOut[2];
                f.base[lane] = base;
                f.sx[lane] = sOut[0];
                f.sy[lane] = sOut[1];
                f.sz[lane] = sOut[2];
            };
            // The tile's vertices by neighbour count (buildSlots: 3, 4, 5, 6, others).
            const uint32_t *const order = valenceOrder0;
            const uint32_t *const group = valenceGroups0 + kValenceGroups * (firstVertex / kTileSize);
            using Count = uint32_t;
            for (uint32_t i = group[0]; i < group[1]; ++i)
                fitVertex(order[i], std::integral_constant<Count, 3>());
            for (uint32_t i = group[1]; i < group[2]; ++i)
                fitVertex(order[i], std::integral_constant<Count, 4>());
            for (uint32_t i = group[2]; i < group[3]; ++i)
                fitVertex(order[i], std::integral_constant<Count, 5>());
            for (uint32_t i = group[3]; i < group[4]; ++i)
                fitVertex(order[i], std::integral_constant<Count, 6>());
            for (uint32_t i = group[4]; i < group[5]; ++i)
                fitVertex(order[i], std::integral_constant<Count, 0>());
            if (turns)
                anyTurning.store(true, std::memory_order_relaxed);
        });
    s.anyTurning = anyTurning.load();
    // n . d with this pass's normals, slot by slot.
    Offset *const offset = s.offset;
    s.threads.forRanges(s.freeSlots, kVertexGrain, [offset, fit](size_t first, size_t last) {
        alignas(16) float along[4];
        for (size_t block = first / 4; block < last / 4; ++block) {
            alongNormalOfBlock(fit[block], offset + 4 * block, along);
            for (int lane = 0; lane < 4; ++lane)
                offset[4 * block + lane].alongNormal = along[lane];
        }
    });
}

namespace {

// Each vertex of the block on its own, from its corner list.
template <bool kQuads>
VOXELFAIR_NOINLINE void moveIrregularBlock(FairingState<kQuads> &s, size_t block) {
    const FitBlock &f = s.fit[block];
    for (int lane = 0; lane < 4; ++lane) {
        const uint32_t v = s.vertexAt[4 * block + lane];
        if (v == kNone)
            continue;
        Offset &o = s.offset[4 * block + lane];
        const glm::vec3 n = f.n(lane);
        float along = f.base[lane] - glm::dot(f.sumS(lane), o.d);
        for (uint32_t i = s.vertexStart[v]; i < s.vertexStart[v + 1]; ++i) {
            const uint32_t u = s.vertexNext[i];
            const glm::vec3 e = s.edgeTerm(n, u);
            if (glm::dot(e, e) > 2.0f)
                along += glm::dot(e, s.offset[s.rank[u]].d);
        }
        moveFreeVertex(f, lane, along, s.half, o);
    }
}

}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void sweep(FairingState<kQuads> &s, bool forward) {
    // On a sharp edge line: towards the plane of each polygon through its centroid.
    const Polygons<kQuads> k = s.k;
    const auto at = s.currentAt();
    for (size_t line = 0; line < s.lineVertices.size(); ++line) {
        const uint32_t v = s.lineVertices[line];
        Offset &o = s.offset[s.rank[v]];
        const glm::vec3 x = s.input[v] + o.d;
        glm::vec3 move(0.0f);
        for (uint32_t j = s.linePolygonStart[line]; j < s.linePolygonStart[line + 1]; ++j) {
            const uint32_t p = s.linePolygons[j];
            glm::vec3 centroid(0.0f);
            for (uint32_t c = k.first(p); c < k.last(p); ++c)
                centroid += at(c);
            centroid /= float(k.arity(p));
            move += s.normal[p] * glm::dot(s.normal[p], centroid - x);
        }
        move /= float(s.linePolygonStart[line + 1] - s.linePolygonStart[line]);
        o.d = glm::clamp(o.d + move, -s.half, s.half);
    }
    // Free vertices, alternating direction so that no side of the mesh leads.
    const FitBlock *const fit = s.fit;
    const uint32_t *const neighbours = s.slotNeighbours;
    const uint8_t *const regular = s.regularBlock;
    Offset *const offset = s.offset;
    const size_t blocks = s.freeSlots / 4;
    const float half = s.half;
    for (size_t i = 0; i < blocks; ++i) {
        const size_t block = forward ? i : blocks - 1 - i;
        if (regular[block])
            moveFreeBlock(fit[block], neighbours + 4 * kRegularValence * block, offset, offset + 4 * block, half);
        else
            moveIrregularBlock(s, block);
    }
}

template <bool kQuads>
VOXELFAIR_NOINLINE void finish(FairingState<kQuads> &s) {
    const float moved2 = 1e-12f * s.report.voxelSize * s.report.voxelSize, wall = s.half * (1.0f - 1e-5f);
    // Vertex by vertex in ranges split between the threads; the counts and the maximum do not
    // depend on the order.
    std::atomic<size_t> moved{0}, clamped{0};
    std::atomic<uint32_t> maxMove2Bits{0};  // a non-negative float's bits order as the float
    s.threads.forRanges(s.V, kVertexGrain, [&](size_t first, size_t last) {
        float maxMove2 = 0.0f;
        size_t movedHere = 0, clampedHere = 0;
        for (size_t v = first; v < last; ++v) {
            if (!isFree(s.kind[v]) && s.kind[v] != VertexKind::EdgeLine)
                continue;
            const glm::vec3 d = s.offset[s.rank[v]].d;
            s.positions[v] = s.input[v] + d;
            const float d2 = glm::dot(d, d);
            maxMove2 = std::max(maxMove2, d2);
            movedHere += d2 > moved2;
            clampedHere += std::max(std::abs(d.x), std::max(std::abs(d.y), std::abs(d.z))) >= wall;
        }
        moved += movedHere;
        clamped += clampedHere;
        uint32_t bits = 0;
        std::memcpy(&bits, &maxMove2, sizeof bits);
        for (uint32_t seen = maxMove2Bits.load(); seen < bits && !maxMove2Bits.compare_exchange_weak(seen, bits);) {
        }
    });
    float maxMove2 = 0.0f;
    const uint32_t bits = maxMove2Bits.load();
    std::memcpy(&maxMove2, &bits, sizeof bits);
    s.report.movedVertices = moved;
    s.report.clampedVertices = clamped;
    s.report.maxDisplacement = std::sqrt(maxMove2);
}

template <bool kQuads>
void lendAnchorNormals(FairingState<kQuads> &s) {
    for (size_t i = 0; i < s.anchored.size(); ++i)
        s.vertexNormal[s.anchored[i]].n = s.anchoredNormal[i];
}

template <bool kQuads>
void holdAnchors(FairingState<kQuads> &s) {
    for (size_t i = 0; i < s.anchored.size(); ++i) {
        const uint32_t slot = s.rank[s.anchored[i]];
        FitBlock &f = s.fit[slot / 4];
        const int lane = int(slot % 4);
        const glm::vec3 n = s.anchoredNormal[i];
        f.stepScale[lane] = f.base[lane] = f.sx[lane] = f.sy[lane] = f.sz[lane] = 0.0f;
        f.nx[lane] = n.x;
        f.ny[lane] = n.y;
        f.nz[lane] = n.z;
        s.offset[slot].d = s.anchoredOffset[i];
        s.offset[slot].alongNormal = glm::dot(n, s.anchoredOffset[i]);
    }
}

template void lendAnchorNormals(FairingState<true> &);
template void lendAnchorNormals(FairingState<false> &);
template void holdAnchors(FairingState<true> &);
template void holdAnchors(FairingState<false> &);
template void fitFreeVertices(FairingState<true> &);
template void fitFreeVertices(FairingState<false> &);
template void sweep(FairingState<true> &, bool);
template void sweep(FairingState<false> &, bool);
template void finish(FairingState<true> &);
template void finish(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
