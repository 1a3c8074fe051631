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
// a heavily decimated surface often is, where the projection and the closest point part), the answer is refined to the closest point
// (Ericson, "Real-Time Collision Detection" 5.1.5) among the triangles around that triangle's
// corners that face the same way as `facing`, repeated from the new triangle while it improves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

class SurfaceWalk {
public:
    SurfaceWalk(const glm::vec3 *positions, const uint32_t *triangles, size_t faceCount, size_t vertexCount);

    struct Hit {
        uint32_t face;
        glm::vec3 weights;  // barycentric, >= 0, summing to 1
    };
    // `start` must be a face index; at most `maxSteps` moves.
    Hit project(const glm::vec3 &p, uint32_t start, const glm::vec3 &facing, int maxSteps = 16) const;

private:
    struct Frame {
        glm::vec3 origin, dual1, dual2;  // weights 1, 2 = dot(p - origin, dual)
    };
    std::vector<Frame> frames_;
    std::vector<uint32_t> opposite_;  // half-edge 3f + i -> the other face's half-edge
    const glm::vec3 *positions_;
    const uint32_t *triangles_;
    std::vector<glm::vec3> faceNormals_;                   // unit
    std::vector<float> nearPlane_;                         // squared height under which a projection inside is kept
    std::vector<uint32_t> vertexFaceStart_, vertexFaces_;  // faces around each vertex (CSR)
};

}  // namespace voxelfair
