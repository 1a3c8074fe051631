#include "attributes/triangulate.h"

namespace voxelfair {

size_t countFanTriangles(const uint32_t *polygonOffsets, size_t polygonCount) {
    size_t count = 0;
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t arity = polygonOffsets[p + 1] - polygonOffsets[p];
        if (arity >= 3)
            count += arity - 2;
    }
    return count;
}

PolygonMeshError triangulatePolygons(size_t vertexCount, const uint32_t *polygonOffsets,
                                     const uint32_t *polygonIndices, size_t polygonCount, uint32_t *triangles,
                                     uint32_t *triangleToPolygon) {
    if (PolygonMeshError e = validatePolygons(vertexCount, polygonOffsets, polygonIndices, polygonCount);
        e != PolygonMeshError::None)
        return e;
    size_t t = 0;
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
        for (uint32_t i = first + 1; i + 1 < last; ++i, ++t) {
            triangles[3 * t + 0] = polygonIndices[first];
            triangles[3 * t + 1] = polygonIndices[i];
            triangles[3 * t + 2] = polygonIndices[i + 1];
            if (triangleToPolygon)
                triangleToPolygon[t] = uint32_t(p);
        }
    }
    return PolygonMeshError::None;
}

}  // namespace voxelfair
