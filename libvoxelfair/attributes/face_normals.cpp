#include "attributes/face_normals.h"

#include "mesh/vector_helpers.h"

#include <glm/geometric.hpp>

namespace voxelfair {

glm::vec3 triangleNormal(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
    return normalizedOrZero(glm::cross(b - a, c - a));
}

void computePolygonNormals(const PolygonMesh &mesh, glm::vec3 *polygonNormals) {
    validate(mesh);
    const glm::vec3 *const positions = mesh.positions;
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;
    for (size_t p = 0; p < mesh.polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        glm::vec3 sum(0.0f);
        for (uint32_t i = first + 1; i + 1 < last; ++i)
            sum += triangleNormal(positions[polygonIndices[first]], positions[polygonIndices[i]],
                                  positions[polygonIndices[i + 1]]);
        polygonNormals[p] = normalizedOrZero(sum);
    }
}

}  // namespace voxelfair
