// Polygon connectivity by corners, the indexing every stage of the constrained fairing walks.
//
// Contract: corner c is polygonIndices[c] and stands for the edge from that vertex to the next
// vertex of its polygon (polygons as in mesh/polygon_mesh.h: polygonOffsets has polygonCount + 1
// entries). With kQuads (every polygon a quad: the voxel surface) a corner's polygon, next,
// previous and opposite corners follow from c itself; otherwise from a corner -> polygon table.
// oppositeCorner is only meaningful in a quad (inQuad). areaNormal is the unit normal from the
// polygon's vector area (Newell's method), exact for non-planar polygons too.
#pragma once

#include "fairing/constrained/vec3_simd.h"

#include <cstddef>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::constrained {
inline namespace VOXELFAIR_SIMD_VARIANT {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

template <bool kQuads>
struct Polygons {
    const uint32_t *offsets;
    const uint32_t *indices;
    const uint32_t *polygonTable;  // corner -> polygon (unused with kQuads)

    uint32_t polygonOf(uint32_t c) const {
        if constexpr (kQuads)
            return c >> 2;
        else
            return polygonTable[c];
    }
    uint32_t first(size_t p) const { return kQuads ? uint32_t(4 * p) : offsets[p]; }
    uint32_t last(size_t p) const { return kQuads ? uint32_t(4 * p + 4) : offsets[p + 1]; }
    uint32_t arity(size_t p) const { return last(p) - first(p); }
    bool inQuad(uint32_t c) const { return kQuads || arity(polygonOf(c)) == 4; }
    uint32_t nextCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return (c & ~3u) | ((c + 1) & 3u);
        } else {
            const uint32_t p = polygonOf(c);
            return c + 1 < offsets[p + 1] ? c + 1 : offsets[p];
        }
    }
    uint32_t previousCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return (c & ~3u) | ((c + 3) & 3u);
        } else {
            const uint32_t p = polygonOf(c);
            return c > offsets[p] ? c - 1 : offsets[p + 1] - 1;
        }
    }
    uint32_t nextVertex(uint32_t c) const { return indices[nextCorner(c)]; }
    uint32_t previousVertex(uint32_t c) const { return indices[previousCorner(c)]; }
    // The corner across the quad of corner c (its edge is opposite c's edge).
    uint32_t oppositeCorner(uint32_t c) const {
        if constexpr (kQuads) {
            return c ^ 2u;
        } else {
            const uint32_t first = offsets[polygonOf(c)];
            return first + (c - first + 2) % 4;
        }
    }
};

// Unit normal of polygon [first, last) from its vector area (Newell); a quad's vector area is half
// the cross product of its diagonals. `at(i)` is the position of polygonIndices[i].
template <class Position>
glm::vec3 areaNormal(const Position &at, uint32_t first, uint32_t last) {
    if (last - first == 4)
        return normalizedOrZero(glm::cross(at(first + 2) - at(first), at(first + 3) - at(first + 1)));
    glm::vec3 n(0.0f);
    for (uint32_t i = first; i < last; ++i) {
        const glm::vec3 a = at(i), b = at(i + 1 < last ? i + 1 : first);
        n += glm::vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normalizedOrZero(n);
}

}  // namespace VOXELFAIR_SIMD_VARIANT
}  // namespace voxelfair::constrained
