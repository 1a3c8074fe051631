// The work state of one call of fairConstrained (constrained_fairing.h) and the stages that fill
// it, in the order the driver (constrained_fairing.cpp) runs them, each in its own file:
//
//   polygon_normals.cpp  findNormals, findFairedNormals  finite vertices, live polygons, their unit
//                                                        normals, the voxel size
//   corner_lists.cpp     buildCorners                    corners at each vertex (CSR), twins, creases,
//                                                        the sweep waves
//   edge_classes.cpp     classifyEdges, findVertexKinds  step 1: staircase or genuine edge; free,
//                                                        edge-line or pinned vertex
//   normal_filter.cpp    buildLevels, filterNormals      step 2: a-trous averaging of polygon normals
//   plane_regions.cpp    findPlaneRegions                flat faces at any orientation: vertices
//                                                        held on fitted planes, their lines, corners
//   sweep_layout.cpp     buildSlots                      step 3's memory layout (waves of four)
//   position_fit.cpp     fitFreeVertices, sweep, finish  steps 3 and 4: positions fitted to the
//                        lendAnchorNormals, holdAnchors  normals inside each vertex's cell
//   position_kernel.h    moveFreeBlock                   step 3's update, four vertices in SSE
//   feature_fit.cpp      fitFeatureVertices              step 3b: vertices where the normals turn
//                                                        moved towards their polygons' planes
//   drift_removal.cpp    removeDrift                     step 5: the local mean of the move along
//                                                        the normals taken off (two scales)
//
// Every stage takes the state and documents which arrays it reads and which it fills. Member
// pointers used in hot loops are copied to locals in the stages: stores through the byte arrays
// could alias any member, so the compiler would reload them after each store. kQuads when every
// polygon is a quad (the voxel surface).
#pragma once

#include "fairing/constrained/polygon_corners.h"
#include "fairing/constrained/position_kernel.h"
#include "fairing/constrained/stage_threads.h"
#include "fairing/constrained/work_arena.h"
#include "fairing/constrained_fairing.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

enum class VertexKind : uint8_t {
    Free,           // fitted along its normal to its neighbours (moveFreeBlock)
    FreeIrregular,  // the same through the general path: more than kRegularValence neighbours,
                    // an edge-line neighbour or an edge left out of the fit
    EdgeLine,       // on a line of sharp edges: fitted to the planes of its polygons
    Pinned,         // sharp edges end or meet here, or not selected, or no usable polygon
    Skipped,        // non-finite coordinates
};
inline bool isFree(VertexKind kind) { return kind <= VertexKind::FreeIrregular; }

// Step 1's verdict on the edge of each corner (both corners of a manifold edge agree).
enum EdgeFlag : uint8_t { kConvex = 1, kConcave = 2, kSharp = 4 };
constexpr uint8_t kCrease = kConvex | kConcave;

// The vertex-index tiles the sweeps are ordered in (see sweep_layout.cpp).
constexpr uint32_t kTileSize = 16384;
// FairingState::valenceGroups' entries a tile: the first of each group of valenceOrder, and the end.
constexpr size_t kValenceGroups = 6;

// Threads for a call: options.threads (0: one per hardware thread), one per kVerticesPerThread
// vertices at most (a helper's start and wake-ups cost more than a small mesh's stages).
constexpr size_t kVerticesPerThread = 16384;
inline int stageThreadCount(int requested, size_t vertexCount) {
    const size_t wanted = requested > 0 ? size_t(requested) : std::max(1u, std::thread::hardware_concurrency());
    return int(std::clamp<size_t>(std::min(wanted, vertexCount / kVerticesPerThread), 1, 64));
}

// The corner ranges of buildCorners' counting sort: two a thread, so that a thread that is
// descheduled holds up no more than a quarter of the work with two (corner_lists.cpp).
inline size_t cornerParts(int threads) { return threads > 1 ? 2 * size_t(threads) : 1; }

// A vertex normal, padded to 16 bytes for whole-register loads and stores.
struct alignas(16) VertexNormal {
    glm::vec3 n;
    float unused;
};

// Step 5's arrays by slot (drift_removal.cpp), taken by takeDriftArrays and filled by
// prepareDrift (beside the last pass's sweeps) and removeDrift.
struct DriftArrays {
    float *along = nullptr, *smooth = nullptr;    // n . d and the rounds' other buffer
    float *weight = nullptr;                      // 1 / (1 + neighbours), 0 for empty slots
    float *local = nullptr;                       // the local mean (with wide rounds)
    float *near = nullptr, *nearSpare = nullptr;  // the averaged marks where the shape turns, a spare
    uint32_t *others = nullptr;                   // vertices averaged over their corner lists
    size_t otherCount = 0;
};

template <bool kQuads>
struct FairingState {
    FairingState(glm::vec3 *positions_, size_t vertexCount, const uint32_t *polygonOffsets,
                 const uint32_t *polygonIndices, size_t polygonCount, const uint8_t *vertexSelected,
                 const ConstrainedFairingOptions &options_, ConstrainedFairingReport &report_)
        : positions(positions_), input(positions_), V(vertexCount), P(polygonCount),
          cornerCount(polygonOffsets[polygonCount]), offsets(polygonOffsets), indices(polygonIndices),
          selected(vertexSelected), options(options_), report(report_),
          storedLevels(std::max(options_.normalLevels - 1, 1)), scratch(scratchBytes()), arrays(arraysBytes()),
          threads(stageThreadCount(options_.threads, vertexCount)) {}

    // The arrays that live through the call, in one block.
    size_t arraysBytes() const {
        return Arena::bytes<VertexKind>(V) + Arena::bytes<uint8_t>(P) + Arena::bytes<glm::vec3>(P + 2) +
               Arena::bytes<uint32_t>(kQuads ? 0 : cornerCount) + Arena::bytes<uint32_t>(V + 2) +
               Arena::bytes<uint32_t>(cornerCount) + Arena::bytes<uint32_t>(cornerCount + 8) +
               Arena::bytes<uint32_t>(size_t(storedLevels) * cornerCount) + Arena::bytes<uint32_t>(V);
    }
    // The block for buildCorners' and classifyEdges' temporaries, then for step 3's arrays (see
    // buildSlots; more if the waves need more padding than an eighth of the vertices).
    size_t scratchBytes() const {
        const size_t setup = Arena::bytes<uint32_t>(cornerCount + 8) + Arena::bytes<uint8_t>(cornerCount) +
                             Arena::bytes<uint32_t>(cornerCount / 2 + 1) +
                             Arena::bytes<uint32_t>(cornerParts(stageThreadCount(options.threads, V)) * V);
        return std::max(setup, passesBytes(V + V / 8 + 4));
    }
    size_t passesBytes(size_t freeSlots) const {
        return Arena::bytes<glm::vec3>(P + 2) + Arena::bytes<VertexNormal>(V) + Arena::bytes<uint8_t>(V) +
               Arena::bytes<uint32_t>(V) + Arena::bytes<uint32_t>(freeSlots) +
               Arena::bytes<uint32_t>(kRegularValence * freeSlots) + Arena::bytes<Offset>(freeSlots + V + 1) +
               Arena::bytes<FitBlock>(freeSlots / 4) + Arena::bytes<uint8_t>(freeSlots / 4) + featureFitBytes() +
               driftBytes(freeSlots + V + 1);
    }
    // fitFeatureVertices' lists, taken after step 3's arrays and given back each pass.
    size_t featureFitBytes() const {
        return 3 * Arena::bytes<uint32_t>(V) + Arena::bytes<uint32_t>(V + 1) + Arena::bytes<uint32_t>(cornerCount);
    }
    // step 5's arrays (DriftArrays), taken after step 3's arrays before the last pass's sweeps.
    size_t driftBytes(size_t slots) const { return 6 * Arena::bytes<float>(slots) + Arena::bytes<uint32_t>(V); }
    // The arrays of the setup stages, taken before the first one runs.
    void takeArrays() {
        kind = arrays.take<VertexKind>(V);
        live = arrays.take<uint8_t>(P);
        normal = arrays.take<glm::vec3>(P + 2);
        uint32_t *polygonTable = arrays.take<uint32_t>(kQuads ? 0 : cornerCount);
        for (uint32_t p = 0; !kQuads && p < P; ++p)
            std::fill(polygonTable + offsets[p], polygonTable + offsets[p + 1], p);
        k = Polygons<kQuads>{offsets, indices, polygonTable};
        vertexStart = arrays.take<uint32_t>(V + 2);
        vertexNext = arrays.take<uint32_t>(cornerCount + 8);
        vertexCorners = arrays.take<uint32_t>(cornerCount);
        twin = arrays.take<uint32_t>(size_t(storedLevels) * cornerCount);
        rank = arrays.take<uint32_t>(V);
        vertexPrevious = scratch.take<uint32_t>(cornerCount + 8);
        edgeFlags = scratch.take<uint8_t>(cornerCount);
        creases = scratch.take<uint32_t>(cornerCount / 2 + 1);
    }

    // Current position of the vertex of corner i.
    auto currentAt() const {
        return [this](uint32_t i) { return input[indices[i]] + offset[rank[indices[i]]].d; };
    }
    // Step 2's table of level `level` (see normal_filter.cpp).
    const uint32_t *levelTable(int level) const { return twin + size_t(level) * cornerCount; }
    // The corner entering the polygon twice as far across c's edge as `entry` does, both in quads.
    uint32_t doubled(const uint32_t *entry, uint32_t c) const {
        const uint32_t m = entry[c];
        if (m == kNone || !k.inQuad(m))
            return kNone;
        const uint32_t m2 = entry[k.oppositeCorner(m)];
        return m2 != kNone && k.inQuad(m2) ? m2 : kNone;
    }
    // Step 3's s = n + n_u for the edge to u (a neighbour that is not free lends n).
    glm::vec3 edgeTerm(const glm::vec3 &n, uint32_t u) const { return n + (isFree(kind[u]) ? vertexNormal[u].n : n); }

    glm::vec3 *const positions;
    const glm::vec3 *const input;  // positions stay the input until finish()
    const size_t V, P;
    const uint32_t cornerCount;
    const uint32_t *const offsets, *const indices;
    const uint8_t *const selected;
    const ConstrainedFairingOptions &options;
    ConstrainedFairingReport &report;
    const int storedLevels;  // step 2's tables
    float half = 0.0f;       // the cells' half-width

    Arena scratch, arrays;  // the temporaries, then step 3's arrays; the call's arrays
    StageThreads threads;   // the data-parallel stages' (stage_threads.h)
    Polygons<kQuads> k{};
    VertexKind *kind = nullptr;
    uint8_t *live = nullptr;
    glm::vec3 *normal = nullptr, *filtered = nullptr;  // P + 2: [P] (and [P + 1]) stay zero
    uint32_t *vertexStart = nullptr;                   // CSR of the corners of live polygons at each vertex:
    uint32_t *vertexNext = nullptr;                    // their next vertices (8 more entries: see buildCorners),
    uint32_t *vertexCorners = nullptr;                 // the corners themselves (ascending),
    uint32_t *vertexPrevious = nullptr;                // and, while building, their previous vertices
    uint32_t *twin = nullptr;                          // then step 2's level 0, and the tables of levels 1.. after it
    uint8_t *edgeFlags = nullptr;
    uint32_t *creases = nullptr;  // one corner per edge (the lower), creaseCount of them
    size_t creaseCount = 0;
    std::vector<uint32_t> sharpBoundary, sharpCreases, lineVertices, linePolygonStart, linePolygons;
    // One corner of each notch edge (edge_classes.cpp), which step 2's far levels do not cross.
    std::vector<uint32_t> notches;
    uint32_t *rank = nullptr;  // vertex -> slot (first the waves)
    // The vertices tile by tile, in each those with 3, 4, 5, 6 neighbours, then the others, each
    // group by index (sweep_layout.cpp); valenceGroups: kValenceGroups entries a tile.
    uint32_t *valenceOrder = nullptr;
    std::vector<uint32_t> valenceGroups;

    // Step 3, by slot (see sweep_layout.cpp).
    size_t freeSlots = 0;                  // slots of free vertices (and empty ones): whole blocks
    size_t zeroSlot = 0;                   // the last slot, after the other vertices': offset and along 0
    VertexNormal *vertexNormal = nullptr;  // by vertex
    uint32_t *vertexAt = nullptr;          // free slot -> vertex, kNone when empty
    uint32_t *slotNeighbours = nullptr;    // kRegularValence byte offsets per free slot
    Offset *offset = nullptr;
    FitBlock *fit = nullptr;          // per block of four free slots
    uint8_t *regularBlock = nullptr;  // per block: all its vertices Free (moveFreeBlock)
    uint8_t *turning = nullptr;       // by vertex: a neighbour's normal beyond featureSpread (fitFreeVertices)
    bool anyTurning = false;
    DriftArrays drift;  // step 5's

    // plane_regions.cpp: free vertices held at a fixed offset, lending a normal to their neighbours.
    std::vector<uint32_t> anchored;
    std::vector<glm::vec3> anchoredOffset, anchoredNormal;
};

// The stages (explicitly instantiated for both kQuads in their files).
template <bool kQuads>
bool findNormals(FairingState<kQuads> &s);
template <bool kQuads>
void findFairedNormals(FairingState<kQuads> &s);
template <bool kQuads>
void buildCorners(FairingState<kQuads> &s);
template <bool kQuads>
void classifyEdges(const Polygons<kQuads> &k, const uint32_t *twin, const glm::vec3 *positions,
                   const glm::vec3 *unitNormal, const ConstrainedFairingOptions &options, size_t vertexCount,
                   const uint32_t *creases, size_t creaseCount, uint8_t *flags, std::vector<uint32_t> &sharpBoundary,
                   std::vector<uint32_t> &sharpCreases, std::vector<uint32_t> &notches,
                   ConstrainedFairingReport &report, StageThreads &threads);
template <bool kQuads>
void findVertexKinds(FairingState<kQuads> &s);
template <bool kQuads>
void buildLevels(FairingState<kQuads> &s);
template <bool kQuads>
void filterNormals(FairingState<kQuads> &s, int levels);
template <bool kQuads>
void findPlaneRegions(FairingState<kQuads> &s);
template <bool kQuads>
void buildSlots(FairingState<kQuads> &s);
template <bool kQuads>
void lendAnchorNormals(FairingState<kQuads> &s);
template <bool kQuads>
void holdAnchors(FairingState<kQuads> &s);
template <bool kQuads>
void takeDriftArrays(FairingState<kQuads> &s, int rounds, int wideRounds);
template <bool kQuads>
void prepareDrift(FairingState<kQuads> &s, int rounds, int wideRounds);
template <bool kQuads>
void removeDrift(FairingState<kQuads> &s, int rounds, int wideRounds);
template <bool kQuads>
void fitFreeVertices(FairingState<kQuads> &s);
template <bool kQuads>
void sweep(FairingState<kQuads> &s, bool forward);
template <bool kQuads>
void fitFeatureVertices(FairingState<kQuads> &s);
template <bool kQuads>
void finish(FairingState<kQuads> &s);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
