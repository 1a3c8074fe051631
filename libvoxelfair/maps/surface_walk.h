// Where a point of a decimated surface lies on the surface it was decimated from: starting from
// a guess, walk across the source's triangles to the one whose plane projection of the point
// falls inside it (the "visibility walk" of point location in triangulations, Devillers, Pion and
// Teillaud 2002, carried onto a surface). Each step moves across the edge facing the most negative
// barycentric weight; a walk that leaves the surface (border, non-manifold edge) or runs out of
// steps ends on its last triangle, clamped onto it.
//
// From a nearby start (the source triangle under the same UV, then the previous texel's answer)
// this is the projection of the point onto the local sheet of the source: what a baker's ray
// along the surface normal finds, without a search structure, and never the far side of a thin
// plate (the walk stays on the sheet it starts on).
//
// Where the walk ends outside its last triangle (beyond a ridge or a border), or inside it but
// farther from its plane than a quarter of its longest edge (the point is well off the source, as
// a heavily decimated surface often is, where the projection and the closest point part), or on a
// triangle facing away from `facing` (the decimated surface's shading normal there: the far side
// of a fold or of a thin plate, never what the texel shows), the answer is refined to the closest
// point (Ericson, "Real-Time Collision Detection" 5.1.5) among the triangles around that
// triangle's corners that face the same way as `facing`, repeated from the new triangle while it
// improves (the last triangle itself only if it faces that way too).
#pragma once

#include "base/default_init_allocator.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair {

class SurfaceWalk {
public:
    // `normals` (per vertex, may be null) are kept per face corner for normalAt(). `opposite`, when
    // given, is the triangles' half-edge adjacency as buildEdgeAdjacency (atlas/edge_adjacency.h)
    // finds it (3 f + i -> the other face's half-edge, kNoOpposite on borders and non-manifold
    // edges); else it is built here.
    SurfaceWalk(const glm::vec3 *positions, const glm::vec3 *normals, const uint32_t *triangles, size_t faceCount,
                size_t vertexCount, const uint32_t *opposite = nullptr);

    struct Hit {
        uint32_t face;
        glm::vec3 weights;  // barycentric, >= 0, summing to 1
    };
    // True when p's projection onto face `face`'s plane falls inside it, near the plane, and the
    // face faces the way of `facing` (a positive dot with its normal): the walk's answer when it
    // starts there; w gets its weights either way. The bakers' fast path.
    bool holds(const glm::vec3 &p, uint32_t face, const glm::vec3 &facing, glm::vec3 &w) const {
        const Face &f = faces_[face];
        const glm::vec3 d = p - f.origin;
        const float w1 = glm::dot(d, f.dual1), w2 = glm::dot(d, f.dual2), height = glm::dot(d, f.normal);
        w = glm::vec3(1.0f - w1 - w2, w1, w2);
        return (w.x >= 0.0f) & (w1 >= 0.0f) & (w2 >= 0.0f) & (height * height <= f.nearPlane) &
               (glm::dot(f.normal, facing) > 0.0f);
    }
    // A caller's per-thread scratch for the closest-point refinement: which faces it has measured,
    // as a stamp per source face (sized on first use) and the current generation (O(1) membership,
    // nothing cleared between calls).
    struct Marks {
        std::vector<uint32_t> stamp;
        uint32_t generation = 0;
    };
    // The corner of the most negative weight (the first among equals): it faces the edge
    // (k + 1, k + 2), half-edge (k + 1) % 3, that a walk leaves the face by.
    static int mostNegative(const glm::vec3 &w) {
        int k = 0;
        if (w[1] < w[k])
            k = 1;
        if (w[2] < w[k])
            k = 2;
        return k;
    }
    // `start` must be a face index; at most `maxSteps` moves. Inline: the bakers call it per texel.
    Hit project(const glm::vec3 &p, uint32_t start, const glm::vec3 &facing, Marks &marks, int maxSteps = 16) const {
        uint32_t face = start, previous = UINT32_MAX;
        for (int step = 0;; ++step) {
            const Face &f = faces_[face];
            const glm::vec3 d = p - f.origin;
            const float w1 = glm::dot(d, f.dual1), w2 = glm::dot(d, f.dual2);
            const glm::vec3 w(1.0f - w1 - w2, w1, w2);
            const int k = mostNegative(w);
            if (w[k] >= 0.0f) {
                // Inside, and near the plane compared with the triangle's size: the projection is
                // the closest point, or close to it.
                const float height = glm::dot(d, f.normal);
                if (height * height <= f.nearPlane && glm::dot(f.normal, facing) > 0.0f)
                    return {face, w};
                break;
            }
            const uint32_t across = f.opposite[(k + 1) % 3];
            if (step >= maxSteps || across == UINT32_MAX || across / 3 == previous)
                break;  // out of steps, a border, or a ridge walked back and forth
            previous = face;
            face = across / 3;
        }
        return closestAround(p, face, facing, marks);
    }
    // The face beyond the edge of `face` that a point of weights w on it (as holds() gives them)
    // lies past: across the edge facing the most negative weight, project()'s first step;
    // UINT32_MAX where no weight is negative or that edge is a border or non-manifold.
    uint32_t across(uint32_t face, const glm::vec3 &w) const {
        const int k = mostNegative(w);
        if (w[k] >= 0.0f)
            return UINT32_MAX;
        const uint32_t h = faces_[face].opposite[(k + 1) % 3];
        return h == UINT32_MAX ? UINT32_MAX : h / 3;
    }
    // The vertex normals interpolated at a hit (not normalised).
    glm::vec3 normalAt(const Hit &hit) const { return normalAt(hit.face, hit.weights); }
    glm::vec3 normalAt(uint32_t face, const glm::vec3 &w) const {
        const glm::vec3 *n = &cornerNormals_[3 * size_t(face)];
        return w.x * n[0] + w.y * n[1] + w.z * n[2];
    }

    // Everything a step reads, in one 64-byte record per face: weights 1, 2 = dot(p - origin,
    // dual1/2), the unit normal, the squared height under which a projection inside is kept, and
    // the half-edges across each edge (3f + i -> the other face's half-edge).
    struct alignas(64) Face {
        glm::vec3 origin, dual1, dual2, normal;
        float nearPlane;
        uint32_t opposite[3];
    };
    // A face's record and its 3 corner normals, for a caller's own (vectorised) holds().
    const Face &record(uint32_t face) const { return faces_[face]; }
    const glm::vec3 *cornerNormals(uint32_t face) const { return &cornerNormals_[3 * size_t(face)]; }

private:
    Hit closestAround(const glm::vec3 &p, uint32_t face, const glm::vec3 &facing, Marks &marks) const;
    // Written in full by the constructor: not zeroed first (base/default_init_allocator.h).
    std::vector<Face, DefaultInitAllocator<Face>> faces_;
    std::vector<glm::vec3, DefaultInitAllocator<glm::vec3>> cornerNormals_;  // 3 per face
    const glm::vec3 *positions_;
    const uint32_t *triangles_;
    std::vector<uint32_t> vertexFaceStart_;  // faces around each vertex (CSR)
    std::vector<uint32_t, DefaultInitAllocator<uint32_t>> vertexFaces_;
};

}  // namespace voxelfair
