// Step 3b of the constrained fairing (constrained_fairing.h): vertices where the filtered normals
// turn (edges and rims the staircase hides, where step 1 found no genuine edge) are moved towards
// the planes of their polygons.
//
// Why: step 3 moves a vertex only along its own normal so that its edges become perpendicular to
// the mean of two vertex normals. That holds exactly on a sphere, but where the normals of the
// polygons around a vertex differ (a turned box's edge, a cylinder's rim, a wedge's ridge) no
// move along one normal can put the vertex on both planes. The update of Sun, Rosin, Martin and
// Langbein ("Fast and effective feature-preserving mesh denoising", IEEE TVCG 13(5), 2007, their
// eq. 6) can: each polygon p around v pulls v towards its plane through its centroid c_p,
//     x_v <- x_v + 1/|P_v| sum_p n_p (n_p . (c_p - x_v)),
// and where two or three planes meet the vertex settles on their line or corner. Away from such
// vertices it gives nothing step 3 does not, and costs more, so it runs only where it helps.
//
// Contract (fitFeatureVertices; reads normal (the filtered polygon normals), kind, turning, input,
// offset, anchored; writes offset[.].d of the vertices it moves): a feature vertex is a free
// vertex, not anchored, whose vertex normal is more than options.featureSpreadDegrees from a
// neighbour's (turning, found by fitFreeVertices on the way; nothing to do when none is). Each of
// options.featureFitIterations Gauss-Seidel sweeps, in vertex order, applies the update above to
// every feature vertex (centroids at the current positions), clamped into its cell (step 4).
// Counts the feature vertices into report.featureVertices (the last pass's).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

template <bool kQuads>
VOXELFAIR_NOINLINE void fitFeatureVertices(FairingState<kQuads> &s) {
    const int iterations = s.options.featureFitIterations;
    s.report.featureVertices = 0;
    if (iterations <= 0 || !s.anyTurning)
        return;
    const Polygons<kQuads> k = s.k;
    const size_t V = s.V, P = s.P;
    const uint32_t *const indices = s.indices, *const rank = s.rank;
    const uint8_t *const live = s.live;
    const glm::vec3 *const normal = s.normal;
    // The lists live in the scratch block after step 3's arrays (FairingState::passesBytes has
    // room for them) and die at the end of the pass.
    const Arena::Mark mark = s.scratch.mark();
    uint32_t *const first = s.scratch.template take<uint32_t>(V);  // each vertex's feature index
    for (size_t v = 0; v < V; ++v)
        first[v] = isFree(s.kind[v]) && s.turning[v] ? 0u : kNone;
    for (uint32_t v : s.anchored)  // held on their planes (plane_regions.cpp)
        first[v] = kNone;
    uint32_t *const features = s.scratch.template take<uint32_t>(V);
    uint32_t count = 0;
    for (size_t v = 0; v < V; ++v)
        if (first[v] != kNone) {
            first[v] = count;
            features[count++] = uint32_t(v);
        }
    s.report.featureVertices = count;
    if (count == 0) {
        s.scratch.rewind(mark);
        return;
    }
    // Each feature vertex's live polygons, counting-sorted: polygons[start[f] .. start[f + 1]).
    uint32_t *const start = s.scratch.template take<uint32_t>(size_t(count) + 1);
    std::fill(start, start + count + 1, 0u);
    for (size_t p = 0; p < P; ++p)
        if (live[p])
            for (uint32_t c = k.first(p); c < k.last(p); ++c)
                if (first[indices[c]] != kNone)
                    ++start[first[indices[c]] + 1];
    for (uint32_t f = 0; f < count; ++f)
        start[f + 1] += start[f];
    uint32_t *const polygons = s.scratch.template take<uint32_t>(start[count]);
    uint32_t *const fill = s.scratch.template take<uint32_t>(count);
    std::copy(start, start + count, fill);
    for (size_t p = 0; p < P; ++p)
        if (live[p])
            for (uint32_t c = k.first(p); c < k.last(p); ++c)
                if (first[indices[c]] != kNone)
                    polygons[fill[first[indices[c]]]++] = uint32_t(p);

    const auto at = s.currentAt();
    const float half = s.half;
    for (int iteration = 0; iteration < iterations; ++iteration)
        for (uint32_t f = 0; f < count; ++f) {
            const uint32_t v = features[f];
            Offset &o = s.offset[rank[v]];
            const glm::vec3 x = s.input[v] + o.d;
            glm::vec3 move(0.0f);
            for (uint32_t i = start[f]; i < start[f + 1]; ++i) {
                const uint32_t p = polygons[i];
                glm::vec3 centroid(0.0f);
                for (uint32_t c = k.first(p); c < k.last(p); ++c)
                    centroid += at(c);
                centroid /= float(k.arity(p));
                move += normal[p] * glm::dot(normal[p], centroid - x);
            }
            o.d = glm::clamp(o.d + move / float(start[f + 1] - start[f]), -half, half);
        }
    s.scratch.rewind(mark);
}

template void fitFeatureVertices(FairingState<true> &);
template void fitFeatureVertices(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
