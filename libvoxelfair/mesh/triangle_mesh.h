// The triangulated twin of PolygonMesh (polygon_mesh.h): a view on caller-owned arrays, three
// vertex indices per face, counter-clockwise seen from outside, in the style of xatlas's MeshDecl.
// What attributes/triangulate.h writes and what the atlas (paper §4.5) and the maps read; a stage
// adds its own per-face or per-corner arrays by deriving from it (atlas/atlas_mesh.h). Nothing is
// copied; the arrays must outlive the calls that take the view.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair {

struct TriangleMesh {
    const glm::vec3 *positions = nullptr;
    size_t vertexCount = 0;
    const uint32_t *triangles = nullptr;  // 3 per face
    size_t faceCount = 0;
};

inline TriangleMesh triangleMesh(const std::vector<glm::vec3> &positions, const std::vector<uint32_t> &triangles) {
    return {positions.data(), positions.size(), triangles.data(), triangles.size() / 3};
}

// Throws MeshError (base/error.h) unless the faces are valid: vertexCount and faceCount within
// 32-bit indices, the triangle array present when there are faces and every index < vertexCount,
// positions present when faces use them. The message names the first bad face. A mesh without
// faces is valid (an empty result, not an error).
void validate(const TriangleMesh &mesh);

}  // namespace voxelfair
