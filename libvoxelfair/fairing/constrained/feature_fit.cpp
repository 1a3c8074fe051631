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
//
// The planes' normals. The filtered normals turn over several quads where the true surface turns
// at a line (step 2 averages across edges it took for staircase steps), so planes with those
// normals hold a rounded edge. With options.featureFlatDegrees > 0, each polygon p around a
// feature vertex takes instead the normal of a flat side near it: walking straight across each
// of p's edges (step 2's tables), the polygon 4 quads away is a side; it is flat as far as its
// normal agrees with the polygon 2 quads away on that walk and with the polygons 2 quads away
// from it across each of its own edges (a plane, not a curved patch: spheres, cylinders and tori
// fail this). Each side weighs flatness (1 within featureFlatDegrees / 2, 0 beyond 1.5 times it)
// times nearness to n_p (1 within 30 degrees, 0 beyond 60), both ramps in the cosine; the sides
// are blended with weights growing as exp(50 cos), so the nearest one wins, and that blend
// replaces n_p as far as the strongest weight says (n_p stays where no side is flat). The band
// of turning normals splits into its two sides and the vertices settle on the line where they
// meet. Every weight is continuous in the normals, so the SSE and scalar variants stay within
// float noise of each other. The snapped normals go to `filtered` (free between step 2's rounds).
#include "fairing/constrained/fairing_state.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

namespace {

constexpr float kSnapDegrees[2] = {60.0f, 30.0f};  // nearness to n_p: 0 beyond the first, 1 within the second
constexpr float kSharpness = 50.0f;                // of the sides' weights by their cosine to n_p

// Writes to s.filtered[p], for each of the `count` polygons listed, the normal of its nearest flat
// side, or normal[p] (see the contract above).
template <bool kQuads>
void snapToFlatSides(FairingState<kQuads> &s, const uint32_t *polygons, uint32_t count) {
    const Polygons<kQuads> k = s.k;
    const glm::vec3 *const normal = s.normal;
    glm::vec3 *const snapped = s.filtered;
    const uint32_t *const twoAway = s.levelTable(std::min(1, s.storedLevels - 1));
    // Weights ramp from 0 to 1 between two angles, so that the result moves continuously with the
    // normals (the SSE and scalar variants agree within float noise).
    const float flatDegrees = s.options.featureFlatDegrees;
    const float cosFlat = std::cos(glm::radians(1.5f * flatDegrees));
    const float cosFlatFull = std::cos(glm::radians(0.5f * flatDegrees));
    const float cosSnap = std::cos(glm::radians(kSnapDegrees[0]));
    const float cosSnapFull = std::cos(glm::radians(kSnapDegrees[1]));
    auto ramp = [](float cosine, float zero, float one) {
        return std::clamp((cosine - zero) / (one - zero), 0.0f, 1.0f);
    };
    // How flat the side at polygon q with normal n is: 1 when the polygons 2 quads around agree.
    auto flatAround = [&](uint32_t q, const glm::vec3 &n) {
        float least = 1.0f;
        for (uint32_t c = k.first(q); c < k.last(q); ++c)
            if (twoAway[c] != kNone)
                least = std::min(least, glm::dot(normal[k.polygonOf(twoAway[c])], n));
        return least;
    };
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t p = polygons[i];
        const glm::vec3 n = normal[p];
        glm::vec3 sum(0.0f);
        float strongest = 0.0f;
        for (uint32_t c = k.first(p); c < k.last(p); ++c) {
            const uint32_t near = twoAway[c], far = s.doubled(twoAway, c);
            if (near == kNone || far == kNone)
                continue;
            const glm::vec3 side = normal[k.polygonOf(far)];
            const float cosine = glm::dot(side, n);
            const float flatness =
                std::min(glm::dot(normal[k.polygonOf(near)], side), flatAround(k.polygonOf(far), side));
            const float weight = ramp(flatness, cosFlat, cosFlatFull) * ramp(cosine, cosSnap, cosSnapFull);
            if (weight <= 0.0f)
                continue;
            strongest = std::max(strongest, weight);
            sum += side * (weight * std::exp(kSharpness * (cosine - 1.0f)));  // the nearest side wins
        }
        snapped[p] = strongest > 0.0f ? glm::normalize(strongest * glm::normalize(sum) + (1.0f - strongest) * n) : n;
    }
}

}  // namespace

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

    // The planes' normals: the filtered ones, or their flat sides' (see snapToFlatSides).
    const glm::vec3 *fitNormal = normal;
    if (s.options.featureFlatDegrees > 0.0f) {
        snapToFlatSides(s, polygons, start[count]);
        fitNormal = s.filtered;
    }
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
                move += fitNormal[p] * glm::dot(fitNormal[p], centroid - x);
            }
            o.d = glm::clamp(o.d + move / float(start[f + 1] - start[f]), -half, half);
        }
    s.scratch.rewind(mark);
}

template void fitFeatureVertices(FairingState<true> &);
template void fitFeatureVertices(FairingState<false> &);

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
