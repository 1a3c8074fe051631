// Step 1 of the constrained fairing (constrained_fairing.h): which edges stay sharp, and from
// them what each vertex may do.
//
// Contract (classifyEdges; any order of the lists gives the same verdicts): every crease (one
// corner per edge: polygons meeting at more than creaseAngle) is flagged kConvex or kConcave on
// both corners; every corner in sharpBoundary (no twin) gets kSharp. With keepSharpEdges, a crease
// is a staircase step when a polygon beside it is a riser: within stepReach quads, walking across
// flat quads away from the crease, the next crease turns the other way. Otherwise it is genuine
// (kSharp on both corners, listed in sharpCreases), unless the walks on both of its sides end,
// within featureReach quads, on staircase steps (a lone straight edge in a rounded part), or it
// is an isolated single edge (its two ends touch no other genuine edge). Counts into the report.
// A crease with a single notch on one side (a riser and a tread, each within stepReach quads) and
// flats of at least options.cornerFlats quads beyond the notch and on its other side, one of them
// 2 quads longer, is a notch edge, listed in `notches` (whatever else it is): step 2's far levels do not
// cross it (normal_filter.cpp).
//
// Why the notch rule (ours): a box turned a few degrees voxelizes each face as one long tread and
// each corner as a 1-voxel notch, which the riser test reads as a staircase; step 2 then spreads
// the corners' normals over the whole face and step 3 bows it into a pillow (a box turned 8.2
// degrees about one axis: RMS 0.275, raw 0.271, the paper's pass 0.249; 0.245 with the rule). A
// small circle's notches look the same but lie between shorter flats (radius 3: 3-4 quads; radius
// 4 at some offsets 5 and 6, as on a torus of tube radius 4), so flats of 5 and 7 leave cylinders,
// capsules, tori and the other families within 0.004 RMS of where they were; the fillets of
// rounded boxes on the lattice (one notch between long flat faces) gain from it too (mean RMS of 8
// instances 0.092 -> 0.084).
// The idea of separating staircase from feature edges is from Moench, Adler and Preim,
// "Staircase-aware smoothing of medical surface meshes" (VCBM 2010); the riser test is ours.
//
// Contract (findVertexKinds): a vertex with 2 sharp edges is EdgeLine (its polygons listed in
// linePolygons); with 1 (unless options.freeEdgeEnds) or 3+, or unselected, or without live
// polygons, Pinned; otherwise Free, or FreeIrregular when it has more than kRegularValence
// neighbours or an EdgeLine neighbour.
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <atomic>
#include <utility>

#include <glm/geometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {
constexpr size_t kCreaseGrain = 4096;  // creases a thread takes at a time
}  // namespace

template <bool kQuads>
VOXELFAIR_NOINLINE void
classifyEdges(const Polygons<kQuads> &k, const uint32_t *twin, const glm::vec3 *positions, const glm::vec3 *unitNormal,
              const ConstrainedFairingOptions &options, size_t vertexCount, const uint32_t *creases, size_t creaseCount,
              uint8_t *flags, std::vector<uint32_t> &sharpBoundary, std::vector<uint32_t> &sharpCreases,
              std::vector<uint32_t> &notches, ConstrainedFairingReport &report, StageThreads &threads) {
    // Convex or concave: the far end of the other polygon's next edge lies below this polygon's
    // plane, or not. (Creases in ranges split between the threads: each edge's two corners are
    // its own.)
    threads.forRanges(creaseCount, kCreaseGrain, [&](size_t first, size_t last) {
        for (const uint32_t *crease = creases + first; crease != creases + last; ++crease) {
            const uint32_t c = *crease, t = twin[c];  // t runs b -> a
            const uint32_t a = k.indices[c], far = k.nextVertex(k.nextCorner(t));
            flags[c] = flags[t] =
                glm::dot(unitNormal[k.polygonOf(c)], positions[far] - positions[a]) < 0.0f ? kConvex : kConcave;
        }
    });
    report.creaseEdges = creaseCount;
    for (uint32_t c : sharpBoundary)
        flags[c] |= kSharp;
    report.sharpEdges = sharpBoundary.size();
    if (!options.keepSharpEdges)
        return;

    // Walks across quads away from the edge of corner c, through flat edges, to the next crease:
    // its corner and how many quads were crossed (kNone past maxSteps, at a boundary or at a
    // polygon that is not a quad).
    struct WalkEnd {
        uint32_t corner = kNone;
        int steps = 0;
    };
    auto walk = [&](uint32_t c, int maxSteps) {
        for (int step = 1; step <= maxSteps && k.inQuad(c); ++step) {
            const uint32_t opposite = k.oppositeCorner(c);
            if (flags[opposite] & kCrease)
                return WalkEnd{opposite, step};
            if (twin[opposite] == kNone)
                break;
            c = twin[opposite];
        }
        return WalkEnd{};
    };
    auto turn = [&](uint32_t c) { return flags[c] & kCrease; };

    // A corner of a box turned a few degrees from the lattice: on one side of crease c the walk
    // turns back within stepReach (a riser), turns again the same way as c within stepReach (a
    // tread: a single notch), and beyond it a flat of cornerFlats quads or more; on c's other side
    // a flat as long; one of the two flats at least cornerFlats + 2.
    const int flats = options.cornerFlats;
    auto notchCorner = [&](uint32_t c, uint32_t t) {
        if (flats <= 0)
            return false;
        // (Cheap first: most creases have another one quad across on both sides.)
        const bool flat[2] = {!k.inQuad(c) || !(flags[k.oppositeCorner(c)] & kCrease),
                              !k.inQuad(t) || !(flags[k.oppositeCorner(t)] & kCrease)};
        if (!flat[0] && !flat[1])
            return false;
        // A flat's length as far as it matters: flats + 2 when no crease ends it within flats + 1.
        auto length = [&](uint32_t from) {
            const WalkEnd end = walk(from, flats + 1);
            return end.corner == kNone ? flats + 2 : end.steps;
        };
        for (int side = 0; side < 2; ++side) {
            const uint32_t in = side == 0 ? c : t, out = side == 0 ? t : c;
            if (!flat[1 - side])
                continue;
            const int outside = length(out);
            if (outside <= flats - 1)
                continue;
            const WalkEnd riser = walk(in, options.stepReach);
            if (riser.corner == kNone || turn(riser.corner) == turn(c) || twin[riser.corner] == kNone)
                continue;
            const WalkEnd tread = walk(twin[riser.corner], options.stepReach);
            if (tread.corner == kNone || turn(tread.corner) != turn(c) || twin[tread.corner] == kNone)
                continue;
            // (One flat 2 quads longer: a circle of radius 4 can show a single notch between
            // flats of 5 and 6.)
            const int beyond = length(twin[tread.corner]);
            if (beyond >= flats && std::max(beyond, outside) >= flats + 2)
                return true;
        }
        return false;
    };

    struct Candidate {
        uint32_t corner;
        bool thin;
    };
    // The verdicts read only the crease flags: creases in ranges split between the threads, each
    // listing its notches and candidates, joined in the ranges' order and flagged after.
    const size_t chunks = (creaseCount + kCreaseGrain - 1) / kCreaseGrain;
    std::vector<std::vector<uint32_t>> notchesIn(chunks);
    std::vector<std::vector<Candidate>> candidatesIn(chunks);
    threads.run(chunks, [&](size_t chunk) {
        const uint32_t *const end = creases + std::min(creaseCount, (chunk + 1) * kCreaseGrain);
        for (const uint32_t *crease = creases + chunk * kCreaseGrain; crease != end; ++crease) {
            const uint32_t c = *crease, t = twin[c];
            if (notchCorner(c, t))
                notchesIn[chunk].push_back(c);
            // Most creases of a staircase turn back one quad away on either side: a step, whatever
            // the walks find further (the nearest crease decides below).
            if (k.inQuad(c) && (flags[k.oppositeCorner(c)] & kCrease) && turn(k.oppositeCorner(c)) != turn(c))
                continue;
            if (k.inQuad(t) && (flags[k.oppositeCorner(t)] & kCrease) && turn(k.oppositeCorner(t)) != turn(c))
                continue;
            const WalkEnd side[2] = {walk(c, options.stepReach), walk(t, options.stepReach)};
            // The nearest crease within stepReach decides: turning back = a riser (staircase);
            // turning the same way one quad away = a 1-voxel plate or rod (genuine).
            int nearest = options.stepReach + 1;
            for (const WalkEnd &end : side)
                if (end.corner != kNone)
                    nearest = std::min(nearest, end.steps);
            bool step = false, sameAtNearest = false;
            for (const WalkEnd &end : side)
                if (end.corner != kNone && end.steps == nearest)
                    (turn(end.corner) != turn(c) ? step : sameAtNearest) = true;
            const bool isThin = !step && sameAtNearest && nearest == 1;
            if (!step && !isThin)
                for (const WalkEnd &end : side)
                    if (end.corner != kNone && turn(end.corner) != turn(c))
                        step = true;
            if (step)
                continue;
            candidatesIn[chunk].push_back({c, isThin});
        }
    });
    std::vector<Candidate> candidates;
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
        notches.insert(notches.end(), notchesIn[chunk].begin(), notchesIn[chunk].end());
        candidates.insert(candidates.end(), candidatesIn[chunk].begin(), candidatesIn[chunk].end());
    }
    for (const Candidate &candidate : candidates) {
        flags[candidate.corner] |= kSharp;
        flags[twin[candidate.corner]] |= kSharp;
    }
    if (candidates.empty())
        return;
    auto unsharpen = [&](uint32_t c) {
        flags[c] &= uint8_t(~kSharp);
        flags[twin[c]] &= uint8_t(~kSharp);
    };
    // A straight edge whose faces end, both ways, on staircase steps is a flat run of a rounded
    // part (a circle of radius 3 voxelizes with a 5-voxel straight corner).
    // (The walks read the flags, which change only after them: candidates in ranges split between
    // the threads, each listing its demoted edges.)
    if (options.featureReach > 0) {
        const size_t candidateChunks = (candidates.size() + kCreaseGrain - 1) / kCreaseGrain;
        std::vector<std::vector<uint32_t>> demotedIn(candidateChunks);
        threads.run(candidateChunks, [&](size_t chunk) {
            for (size_t i = chunk * kCreaseGrain; i < std::min(candidates.size(), (chunk + 1) * kCreaseGrain); ++i) {
                const uint32_t c = candidates[i].corner;
                if (candidates[i].thin)
                    continue;
                const uint32_t a = walk(c, options.featureReach).corner, b = walk(twin[c], options.featureReach).corner;
                if (a != kNone && b != kNone && !(flags[a] & kSharp) && !(flags[b] & kSharp))
                    demotedIn[chunk].push_back(c);
            }
        });
        for (const std::vector<uint32_t> &demoted : demotedIn)
            for (uint32_t c : demoted)
                unsharpen(c);
    }
    // A single sharp edge touching no other is a corner of a small pole terrace, not a feature.
    std::vector<uint8_t> degree(vertexCount, 0);
    for (const Candidate &candidate : candidates)
        if (flags[candidate.corner] & kSharp)
            for (uint32_t v : {k.indices[candidate.corner], k.nextVertex(candidate.corner)})
                degree[v] = uint8_t(std::min(degree[v] + 1, 2));
    for (const Candidate &candidate : candidates) {
        const uint32_t c = candidate.corner;
        if ((flags[c] & kSharp) && degree[k.indices[c]] == 1 && degree[k.nextVertex(c)] == 1)
            unsharpen(c);
    }
    for (const Candidate &candidate : candidates)
        if (flags[candidate.corner] & kSharp)
            sharpCreases.push_back(candidate.corner);
    report.sharpEdges += sharpCreases.size();
}

template <bool kQuads>
VOXELFAIR_NOINLINE void findVertexKinds(FairingState<kQuads> &s) {
    const Polygons<kQuads> k = s.k;
    const size_t V = s.V;
    VertexKind *const kind = s.kind;
    const uint32_t *const start = s.vertexStart, *const next = s.vertexNext;
    const bool anySharp = !s.sharpBoundary.empty() || !s.sharpCreases.empty();
    std::vector<uint8_t> sharpDegree(anySharp ? V : 0, 0);
    for (const std::vector<uint32_t> *edges : {&s.sharpBoundary, &s.sharpCreases})
        for (uint32_t c : *edges)
            for (uint32_t v : {s.indices[c], k.nextVertex(c)})
                sharpDegree[v] = uint8_t(std::min(sharpDegree[v] + 1, 3));
    // (Vertex ranges split between the threads: each sets its vertices' kinds and lists its edge
    // line vertices, joined in range order; the second loop only turns Free into FreeIrregular,
    // which no vertex reads.)
    const size_t grain = 4 * kCreaseGrain, chunks = (V + grain - 1) / grain;
    std::vector<std::vector<uint32_t>> linesIn(chunks);
    std::atomic<size_t> pinnedCount{0};
    const uint8_t *const selected = s.selected;
    const bool freeEnds = s.options.freeEdgeEnds;
    s.threads.run(chunks, [&](size_t chunk) {
        size_t pinned = 0;
        for (size_t v = chunk * grain; v < std::min(V, (chunk + 1) * grain); ++v) {
            if (kind[v] == VertexKind::Skipped || (!anySharp && !selected && start[v] < start[v + 1]))
                continue;  // (the common case: free)
            const uint8_t degree = anySharp ? sharpDegree[v] : 0;
            const bool pinnedEnd = degree != 0 && degree != 2 && !(freeEnds && degree == 1);
            if ((selected && !selected[v]) || start[v] == start[v + 1] || pinnedEnd) {
                kind[v] = VertexKind::Pinned;
                ++pinned;
            } else if (degree == 2) {
                kind[v] = VertexKind::EdgeLine;
                linesIn[chunk].push_back(uint32_t(v));
            }
        }
        pinnedCount += pinned;
    });
    for (const std::vector<uint32_t> &lines : linesIn)
        s.lineVertices.insert(s.lineVertices.end(), lines.begin(), lines.end());
    s.report.pinnedVertices = pinnedCount.load();
    s.report.edgeLineVertices = s.lineVertices.size();
    const bool anyLine = !s.lineVertices.empty();
    s.threads.forRanges(V, grain, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            if (kind[v] != VertexKind::Free)
                continue;
            bool regular = start[v + 1] - start[v] <= kRegularValence;
            for (uint32_t i = start[v]; anyLine && regular && i < start[v + 1]; ++i)
                regular = kind[next[i]] != VertexKind::EdgeLine;
            if (!regular)
                kind[v] = VertexKind::FreeIrregular;
        }
    });
    s.linePolygonStart.push_back(0);
    for (uint32_t v : s.lineVertices) {
        for (uint32_t i = start[v]; i < start[v + 1]; ++i)
            s.linePolygons.push_back(k.polygonOf(s.vertexCorners[i]));
        s.linePolygonStart.push_back(uint32_t(s.linePolygons.size()));
    }
}

#define VOXELFAIR_INSTANTIATE(kQuads)                                                                                  \
    template void classifyEdges(const Polygons<kQuads> &, const uint32_t *, const glm::vec3 *, const glm::vec3 *,      \
                                const ConstrainedFairingOptions &, size_t, const uint32_t *, size_t, uint8_t *,        \
                                std::vector<uint32_t> &, std::vector<uint32_t> &, std::vector<uint32_t> &,             \
                                ConstrainedFairingReport &, StageThreads &);                                           \
    template void findVertexKinds(FairingState<kQuads> &);
VOXELFAIR_INSTANTIATE(true)
VOXELFAIR_INSTANTIATE(false)
#undef VOXELFAIR_INSTANTIATE

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
