#include "attributes/face_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace voxelfair {

namespace {

glm::vec3 normaliseOrZero(const glm::vec3 &v) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length))
        return glm::vec3(0.0f);
    return v / length;
}

}  // namespace

glm::vec3 triangleNormal(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
    return normaliseOrZero(glm::cross(b - a, c - a));
}

PolygonMeshError computePolygonNormals(const glm::vec3 *positions, size_t vertexCount,
                                       const uint32_t *polygonOffsets, const uint32_t *polygonIndices,
                                       size_t polygonCount, glm::vec3 *polygonNormals) {
    if (PolygonMeshError e = validatePolygons(vertexCount, polygonOffsets, polygonIndices, polygonCount);
        e != PolygonMeshError::None)
        return e;
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        glm::vec3 sum(0.0f);
        for (uint32_t i = first + 1; i + 1 < last; ++i)
            sum += triangleNormal(positions[polygonIndices[first]], positions[polygonIndices[i]],
                                  positions[polygonIndices[i + 1]]);
        polygonNormals[p] = normaliseOrZero(sum);
    }
    return PolygonMeshError::None;
}

}  // namespace voxelfair
