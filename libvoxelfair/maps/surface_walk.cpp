// Walking point location on a triangle surface; the contract is in surface_walk.h.
#include "maps/surface_walk.h"

#include "atlas/edge_adjacency.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace voxelfair {

SurfaceWalk::SurfaceWalk(const glm::vec3 *positions, const glm::vec3 *normals, const uint32_t *triangles,
                         size_t faceCount, size_t vertexCount, const uint32_t *givenOpposite)
    : faces_(faceCount), cornerNormals_(3 * faceCount), positions_(positions), triangles_(triangles),
      vertexFaceStart_(vertexCount + 1, 0), vertexFaces_(3 * faceCount) {
    for (size_t c = 0; c < 3 * faceCount; ++c)
        ++vertexFaceStart_[triangles[c] + 1];
    for (size_t v = 0; v < vertexCount; ++v)
        vertexFaceStart_[v + 1] += vertexFaceStart_[v];
    {
        std::vector<uint32_t> fill(vertexFaceStart_.begin(), vertexFaceStart_.end() - 1);
        for (size_t c = 0; c < 3 * faceCount; ++c)
            vertexFaces_[fill[triangles[c]]++] = uint32_t(c / 3);
    }
    std::vector<uint32_t> built;
    if (!givenOpposite)
        built = buildEdgeAdjacency(triangles, faceCount, vertexCount).opposite;
    const uint32_t *const opposite = givenOpposite ? givenOpposite : built.data();
    for (size_t f = 0; f < faceCount; ++f) {
        const glm::vec3 a = positions[triangles[3 * f]], e1 = positions[triangles[3 * f + 1]] - a,
                        e2 = positions[triangles[3 * f + 2]] - a;
        // Dual basis of (e1, e2) in their plane: dot(dual1, e1) = 1, dot(dual1, e2) = 0, ...
        const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        const float det = d11 * d22 - d12 * d12;
        Face &face = faces_[f];
        face.origin = a;
        const glm::vec3 n = glm::cross(e1, e2);
        const float length = glm::length(n);
        face.normal = length > 0.0f ? n / length : n;
        // A quarter of the longest edge, squared.
        face.nearPlane = 0.0625f * std::max({d11, d22, glm::dot(e2 - e1, e2 - e1)});
        if (det > 0.0f) {
            face.dual1 = (d22 * e1 - d12 * e2) / det;
            face.dual2 = (d11 * e2 - d12 * e1) / det;
        } else {
            face.dual1 = face.dual2 = glm::vec3(0.0f);  // no area: weights (1, 0, 0)
        }
        static_assert(kNoOpposite == UINT32_MAX, "project() tests borders against UINT32_MAX");
        for (int k = 0; k < 3; ++k) {
            face.opposite[k] = opposite[3 * f + size_t(k)];
            cornerNormals_[3 * f + size_t(k)] = normals ? normals[triangles[3 * f + size_t(k)]] : glm::vec3(0.0f);
        }
    }
}

namespace {
// Closest point of triangle abc to p as barycentric weights (Ericson 5.1.5).
glm::vec3 closestWeights(const glm::vec3 &p, const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return {1, 0, 0};
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return {0, 1, 0};
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const float v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return {0, 0, 1};
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const float w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const float sum = va + vb + vc;
    if (!(sum > 0))
        return {1, 0, 0};
    const float v = vb / sum, w = vc / sum;
    return {1 - v - w, v, w};
}
}  // namespace

SurfaceWalk::Hit SurfaceWalk::closestAround(const glm::vec3 &p, uint32_t face, const glm::vec3 &facing,
                                            Marks &marks) const {
    // Off the source: the closest facing point around the last triangle, while it improves.
    auto point = [&](uint32_t f, const glm::vec3 &weights) {
        const uint32_t *t = &triangles_[3 * size_t(f)];
        return weights.x * positions_[t[0]] + weights.y * positions_[t[1]] + weights.z * positions_[t[2]];
    };
    auto closest = [&](uint32_t f) {
        const uint32_t *t = &triangles_[3 * size_t(f)];
        return closestWeights(p, positions_[t[0]], positions_[t[1]], positions_[t[2]]);
    };
    Hit best{face, closest(face)};
    glm::vec3 q = point(face, best.weights);
    // The last triangle is the answer only if it faces the same way or none around does.
    float bestDistance = glm::dot(faces_[face].normal, facing) > 0.0f ? glm::dot(q - p, q - p) : INFINITY;
    // Faces already measured (a face shares the fans of two or three corners, and rounds overlap)
    // are not measured again. Every one is remembered (a stamp per face, this call's generation):
    // measuring one again would give the same distance, and it cannot win. A measured face either
    // lost to the best distance of its time (d >= it), or became the best and later lost the best
    // to a strictly smaller distance; the best distance only decreases, the test is strict, and the
    // current best face is skipped anyway, so it loses again. Hence the same answer as measuring it
    // again (or as remembering only the first 64, as this did before).
    if (marks.stamp.size() != faces_.size())
        marks.stamp.assign(faces_.size(), 0), marks.generation = 0;
    if (++marks.generation == 0) {  // wrapped: old stamps could match again
        std::fill(marks.stamp.begin(), marks.stamp.end(), 0);
        marks.generation = 1;
    }
    uint32_t *const stamp = marks.stamp.data();
    const uint32_t generation = marks.generation;
    stamp[face] = generation;
    auto measured = [&](uint32_t f) {
        if (stamp[f] == generation)
            return true;
        stamp[f] = generation;
        return false;
    };
    // A face whose plane is farther from p than the best distance cannot win (its closest point
    // lies on that plane): it is left after the plane's distance, stamped, without its closest
    // point. Skipped only beyond a margin far above the rounding of either computation
    // (2^-12 of p's largest coordinate plus 1/1000 of the distance, where the floats lose a few
    // 2^-24 of the coordinates, the normal's direction a few 2^-24 over the sine of the
    // triangle's smallest angle), so every skipped face's computed distance would not have been
    // smaller either: the same answers. The best distance only decreases, so it never wins later.
    const float tolerance = 0x1p-12f * (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) + 1.0f);
    float reach = std::sqrt(bestDistance) * 1.001f + tolerance;  // INFINITY while none faces the way
    for (int round = 0; round < 16; ++round) {
        const uint32_t centre = best.face;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = triangles_[3 * size_t(centre) + size_t(k)];
            for (uint32_t i = vertexFaceStart_[v]; i < vertexFaceStart_[v + 1]; ++i) {
                const uint32_t f = vertexFaces_[i];
                // The stamp first: a face seen before in this call (the best one included) is
                // not read again; a face facing away is stamped too (it fails again).
                const Face &record = faces_[f];
                if (measured(f) || glm::dot(record.normal, facing) <= 0.0f ||
                    std::abs(glm::dot(p - record.origin, record.normal)) > reach)
                    continue;
                const glm::vec3 weights = closest(f);
                q = point(f, weights);
                const float d = glm::dot(q - p, q - p);
                if (d < bestDistance) {
                    bestDistance = d, best = {f, weights};
                    reach = std::sqrt(bestDistance) * 1.001f + tolerance;
                }
            }
        }
        if (best.face == centre)
            break;
    }
    return best;
}

}  // namespace voxelfair
