// The polygon mesh the later stages share (fairing, attributes; paper §4.3-4.4): a view on
// caller-owned arrays, nothing copied, in the style of xatlas's MeshDecl and meshoptimizer's index
// buffers of mixed arity. Polygon p uses polygonIndices[polygonOffsets[p] .. polygonOffsets[p + 1]),
// counter-clockwise seen from outside; polygonOffsets holds polygonCount + 1 entries from 0.
// The arrays must outlive the calls that take the view.
//
// PolygonMesh reads the positions; MutablePolygonMesh lets a stage move them in place (the
// fairing) and converts to PolygonMesh for everything else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace voxelfair {

struct PolygonMesh {
    const glm::vec3 *positions = nullptr;
    size_t vertexCount = 0;
    const uint32_t *polygonOffsets = nullptr;  // polygonCount + 1 entries, the first 0
    const uint32_t *polygonIndices = nullptr;  // polygonOffsets[polygonCount] entries
    size_t polygonCount = 0;
    // Optional, one per polygon: its colour (RGBA in [0, 1]) and its part (VXL section, VOX
    // instance). Null when the mesh has none.
    const glm::vec4 *polygonColours = nullptr;
    const int *polygonParts = nullptr;

    size_t indexCount() const { return polygonCount ? polygonOffsets[polygonCount] : 0; }
    uint32_t arity(size_t p) const { return polygonOffsets[p + 1] - polygonOffsets[p]; }
    const uint32_t *polygon(size_t p) const { return polygonIndices + polygonOffsets[p]; }
};

struct MutablePolygonMesh {
    glm::vec3 *positions = nullptr;
    size_t vertexCount = 0;
    const uint32_t *polygonOffsets = nullptr;
    const uint32_t *polygonIndices = nullptr;
    size_t polygonCount = 0;
    const glm::vec4 *polygonColours = nullptr;
    const int *polygonParts = nullptr;

    PolygonMesh view() const {
        return {positions, vertexCount, polygonOffsets, polygonIndices, polygonCount, polygonColours, polygonParts};
    }
    operator PolygonMesh() const { return view(); }  // NOLINT(google-explicit-constructor): a view widens
};

// Views on vectors: `offsets` has one entry more than there are polygons (or is empty).
inline PolygonMesh polygonMesh(const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &offsets,
                               const std::vector<uint32_t> &indices) {
    return {positions.data(), positions.size(), offsets.data(), indices.data(),
            offsets.empty() ? 0 : offsets.size() - 1};
}
inline MutablePolygonMesh mutablePolygonMesh(std::vector<glm::vec3> &positions, const std::vector<uint32_t> &offsets,
                                             const std::vector<uint32_t> &indices) {
    return {positions.data(), positions.size(), offsets.data(), indices.data(),
            offsets.empty() ? 0 : offsets.size() - 1};
}

// Throws MeshError (base/error.h) unless the polygons are valid: offsets present and starting
// at 0 and never decreasing, indices present and every one < vertexCount, vertexCount within
// 32-bit indices, positions present when there are vertices. The message names the first bad
// polygon or index. Null arrays are accepted only with polygonCount == 0 (and vertexCount == 0
// for the positions). Optional arrays are not checked (they have no length to check).
void validate(const PolygonMesh &mesh);

// The same for the polygons alone (positions not needed: adjacency, triangulation).
void validatePolygons(const PolygonMesh &mesh);

}  // namespace voxelfair
